/**
 * Read-back of the voxel volumes (vtkVoxelGIPass::GetVoxelVolume) into vtkImageData: point
 * data "Voxels", origin at the first voxel's centre, spacing the voxel size.
 */
#ifndef VoxelGIVolumeReadback_h
#define VoxelGIVolumeReadback_h

class vtkImageData;

namespace voxelgi
{
class Volume3D;
class VoxelizePass;
struct VoxelGrid;

/// Copy volume `volume` (vtkVoxelGIPass::Volumes) into `image`; the context must be current.
/// False for an unknown volume.
bool ReadVolume(const VoxelizePass& voxels, const Volume3D& radiance, const VoxelGrid& grid,
  int volume, vtkImageData* image);

}

#endif
