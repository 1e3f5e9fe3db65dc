/**
 * Shadow-map option of the voxel lighting: a depth map per directional or spot light,
 * rendered from the light by VTK's own mappers (the actors that are voxelized), and the
 * matrices from grid coordinates to each map's clip space. Point lights have none (the voxel
 * lighting raymarches for them).
 */
#ifndef VoxelGIShadowMaps_h
#define VoxelGIShadowMaps_h

#include "GLHelpers.h"
#include "MapperCopies.h"
#include "ViewRenderer.h" // for ViewRenderer
#include "shader_interface.h"

#include <string>
#include <vector>

class vtkLight;
class vtkWindow;

namespace voxelgi
{
struct Frame;
class LightBlock;

class ShadowMaps
{
public:
  static constexpr int MaxLights = VOXELGI_MAX_LIGHTS;

  /// Choose the lights that get a map (block order) and allocate the maps at the frame's
  /// ShadowMapResolution. Returns false with a message when they cannot be allocated.
  bool Prepare(const Frame& frame, const LightBlock& lights, std::string& error);
  /// Render the maps with the frame's voxelized actors as casters.
  void Run(const Frame& frame, const LightBlock& lights);
  /// Whether any light has a map.
  bool HasMaps() const { return this->Maps.Layers() > 0; }

  /// Per light: layer of its map (-1: none) and column-major grid -> clip matrix.
  const int* GetLayers() const { return this->Layers; }
  const float* GetMatrices() const { return this->Matrices; }

  ShadowMapArray Maps;
  void ReleaseGraphicsResources(vtkWindow* window)
  {
    this->Maps.Release();
    this->Copies.ReleaseGraphicsResources(window);
    this->View.Release();
  }

private:
  ViewRenderer View; // draws through each light's camera
  MapperCopies Copies; // depth-only draws never switch the user's mappers
  int Layers[MaxLights];
  float Matrices[16 * MaxLights];
};

}

#endif
