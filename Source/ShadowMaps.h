/**
 * Shadow-map option of the voxel lighting: a depth map per directional or spot light,
 * rendered from the light by VTK's own mappers (the actors that are voxelized), and the
 * matrices from grid coordinates to each map's clip space. Point lights have none (the voxel
 * lighting raymarches for them).
 */
#ifndef VoxelGIShadowMaps_h
#define VoxelGIShadowMaps_h

#include "GLHelpers.h"

#include <string>
#include <vector>

class vtkLight;
class vtkProp;
class vtkRenderer;

namespace voxelgi
{
struct VoxelGrid;

class ShadowMaps
{
public:
  static constexpr int MaxLights = 16;

  /// Render the maps for `lights` (block order) with `casters`. Returns false with a
  /// message when the maps cannot be allocated.
  bool Render(vtkRenderer* renderer, const std::vector<vtkLight*>& lights,
    const std::vector<vtkProp*>& casters, const VoxelGrid& grid, int size, std::string& error);

  /// Per light: layer of its map (-1: none) and column-major grid -> clip matrix.
  const int* GetLayers() const { return this->Layers; }
  const float* GetMatrices() const { return this->Matrices; }

  ShadowMapArray Maps;
  void ReleaseGraphicsResources() { this->Maps.Release(); }

private:
  int Layers[MaxLights];
  float Matrices[16 * MaxLights];
};

}

#endif
