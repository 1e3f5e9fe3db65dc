/**
 * The renderer's switched-on lights in voxel grid coordinates, in the std140 layout of the
 * `VoxelLightBlock` uniform block (Shaders/lights.glsl), uploaded once per frame and shared by
 * the voxel lighting and the per-pixel composite.
 */
#ifndef VoxelGIVoxelLights_h
#define VoxelGIVoxelLights_h

#include "GLHelpers.h"

#include <array>
#include <vector>

class vtkLight;
class vtkRenderer;

namespace voxelgi
{
struct VoxelGrid;

class VoxelLights
{
public:
  static constexpr int MaxLights = 16;
  static constexpr unsigned int Binding = 0; // uniform buffer binding point

  /// Gather the lights (call after the renderer updated camera-following lights). Returns
  /// true when they differ from the last gathered set. Lights beyond MaxLights are dropped
  /// (counted in `dropped`), so are lights with a negative or non-finite intensity or colour
  /// (counted in `invalid`).
  bool Gather(vtkRenderer* renderer, const VoxelGrid& grid, int& dropped, int& invalid);
  /// Upload and bind to Binding.
  void Bind();
  int GetCount() const { return this->Count; }
  /// The gathered lights, in block order.
  const std::vector<vtkLight*>& GetLights() const { return this->Used; }
  void ReleaseGraphicsResources();

private:
  struct Light
  {
    float Position[4];
    float Direction[4];
    float Color[4];
    float Attenuation[4];
  };
  struct Block
  {
    Light Lights[MaxLights];
    int Info[4];
    float Grid[4];
  };
  Block Data{};
  Block Uploaded{};
  bool HaveUploaded = false;
  int Count = 0;
  std::vector<vtkLight*> Used;
  StorageBuffer Buffer;
};

}

#endif
