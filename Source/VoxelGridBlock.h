/**
 * The voxel grid's uniform buffer (Shaders/voxel_grid.glsl): resolution and voxel size, the
 * one copy every stage's shaders read, bound at VOXELGI_GRID_BLOCK_BINDING.
 */
#ifndef VoxelGIVoxelGridBlock_h
#define VoxelGIVoxelGridBlock_h

#include "GLHelpers.h"

class vtkWindow;

namespace voxelgi
{
struct VoxelGrid;

class VoxelGridBlock
{
public:
  /// Upload `grid` when it changed and bind the buffer.
  void Bind(const VoxelGrid& grid);
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  // std140 layout of VoxelGridBlock
  struct Block
  {
    int Resolution = 0;
    float VoxelSize = 0.f;
    float Padding[2] = { 0.f, 0.f };
  };
  Block Uploaded;
  StorageBuffer Buffer;
};

}

#endif
