/**
 * The renderer's switched-on lights in voxel grid coordinates, in the `VoxelLightBlock` uniform
 * block (Shaders/light_block.h, the one declaration C++ and GLSL share), uploaded when they
 * change and bound at VOXELGI_LIGHT_BLOCK_BINDING for LightVoxels, VoxelBounce and ConeTrace.
 */
#ifndef VoxelGILightBlock_h
#define VoxelGILightBlock_h

#include "GLHelpers.h"
#include "light_block.h"
#include "shader_interface.h"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

class vtkLight;
class vtkRenderer;
class vtkWindow;

namespace voxelgi
{
struct VoxelGrid;

class LightBlock
{
public:
  static constexpr int MaxLights = VOXELGI_MAX_LIGHTS;

  /// Gather the lights (creating VTK's automatic headlight and placing camera-following
  /// lights first, as VTK does while rendering). Returns true when they differ from the last
  /// gathered set. Lights beyond MaxLights are dropped, so are lights with a negative or
  /// non-finite intensity or colour; `warnings` says so, once per pass.
  bool Gather(vtkRenderer* renderer, const VoxelGrid& grid, std::vector<std::string>& warnings);
  /// Upload (when changed) and bind.
  void Bind();
  /// Remember the gathered lights as those the voxels are now lit with.
  void MarkLit();
  /// How far, in degrees, the camera-following lights (headlights and camera lights) turned
  /// since MarkLit(): the largest angle between a light's directions (for a positional one,
  /// also between its directions from the grid's centre). Infinite when anything else of the
  /// lights changed, or none were lit.
  double CameraTurnSinceLit() const;
  int GetCount() const { return this->Count; }
  /// The gathered lights, in block order.
  const std::vector<vtkLight*>& GetLights() const { return this->Used; }
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  using Light = glsl::VoxelLight;
  using Block = glsl::VoxelLightBlock;
  // std140: a struct of four vec4s is 64 bytes, its array's stride too
  static_assert(sizeof(Light) == 64 && offsetof(Light, attenuation) == 48, "not std140");
  static_assert(offsetof(Block, voxelLightInfo) == 64 * MaxLights &&
      sizeof(Block) == 64 * MaxLights + 16,
    "not std140");
  /// One light in grid coordinates, in the block's layout.
  static void Pack(vtkLight* light, const VoxelGrid& grid, Light& packed);

  Block Data{};
  Block Uploaded{};
  bool HaveUploaded = false;
  /// Which entries follow the camera; the lights the voxels were lit with.
  std::array<bool, MaxLights> Follows{};
  Block Lit{};
  std::array<bool, MaxLights> LitFollows{};
  bool HaveLit = false;
  float Centre = 0.0f; // of the grid, in voxels on every axis
  int Count = 0;
  bool WarnedDropped = false;
  bool WarnedInvalid = false;
  std::vector<vtkLight*> Used;
  StorageBuffer Buffer;
};

}

#endif
