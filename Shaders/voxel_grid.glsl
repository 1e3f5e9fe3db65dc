// The voxel grid every stage works in: one uniform buffer (VoxelGridBlock.cxx), filled when the
// grid is fitted. Shaders work in grid coordinates (voxel i spans [i, i+1) on each axis); only
// the CPU side keeps the world origin, in double precision.
layout(std140, binding = VOXELGI_GRID_BLOCK_BINDING) uniform VoxelGridBlock
{
  int voxelResolution; // voxels per axis
  float voxelSize;     // edge length of one voxel, world units
};
