/* The voxel grid's uniform block (voxel_grid.glsl), filled by VoxelGridBlock.cxx. */
#ifndef VOXELGI_VOXEL_GRID_BLOCK
#define VOXELGI_VOXEL_GRID_BLOCK

#include "shader_interface.h"
#include "shader_interop.h"

VOXELGI_INTEROP_BEGIN

VOXELGI_UNIFORM_BLOCK(VoxelGridBlock, VOXELGI_GRID_BLOCK_BINDING)
{
  int voxelResolution; // voxels per axis
  float voxelSize;     // edge length of one voxel, world units
  vec4 voxelSceneLo;   // the scene's bounds in grid coordinates, whole voxels (xyz): cones
  vec4 voxelSceneHi;   // end at their faces, nothing lies beyond
};

VOXELGI_INTEROP_END

#endif
