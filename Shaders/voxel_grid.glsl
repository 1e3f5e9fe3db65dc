// The voxel grid every stage works in: one uniform buffer (declared in voxel_grid_block.h for
// the shaders and VoxelGridBlock.cxx alike), filled when the grid is fitted. Shaders work in
// grid coordinates (voxel i spans [i, i+1) on each axis); only the CPU side keeps the world
// origin, in double precision.
#include "voxel_grid_block.h"
