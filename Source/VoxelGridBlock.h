/**
 * The voxel grid's uniform buffer (Shaders/voxel_grid_block.h, the one declaration C++ and
 * GLSL share): resolution, voxel size and the scene's bounds, the one copy every stage's
 * shaders read, bound at VOXELGI_GRID_BLOCK_BINDING.
 */
#ifndef VoxelGIVoxelGridBlock_h
#define VoxelGIVoxelGridBlock_h

#include "GLHelpers.h"
#include "voxel_grid_block.h"

#include <cstddef>

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
  using Block = glsl::VoxelGridBlock;
  // std140: each scalar on its own 4-byte alignment, each vec4 on 16 bytes
  static_assert(offsetof(Block, voxelSize) == 4 && offsetof(Block, voxelSceneLo) == 16 &&
      sizeof(Block) == 48,
    "not std140");
  Block Uploaded{};
  StorageBuffer Buffer;
};

}

#endif
