/**
 * The renderer's camera seen from the voxel grid: the matrix from normalized device
 * coordinates to grid (voxel) coordinates, composed in double precision so that the large
 * translations of a far-from-origin scene cancel before anything is rounded to float.
 */
#ifndef VoxelGIGridView_h
#define VoxelGIGridView_h

class vtkRenderer;

namespace voxelgi
{
struct VoxelGrid;

/// Column-major 4x4 (for glUniformMatrix4fv); `ndcFromGrid`, if given, gets its inverse.
void GridFromNDC(vtkRenderer* renderer, const VoxelGrid& grid, float columnMajor[16],
  float ndcFromGrid[16] = nullptr);

/// Column-major 3x3 (for glUniformMatrix3fv) from the camera's view-space normals (the
/// G-buffer's) to grid directions: the inverse of the view rotation.
void NormalToGrid(vtkRenderer* renderer, float columnMajor[9]);

}

#endif
