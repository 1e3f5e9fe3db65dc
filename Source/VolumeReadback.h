/**
 * Read-back: the voxel volumes (vtkVoxelGIPass::GetVoxelVolume) into vtkImageData (point
 * data "Voxels", origin at the first voxel's centre, spacing the voxel size), and the float
 * images of the last traced frame (vtkVoxelGIPass::GetFloatImage).
 */
#ifndef VoxelGIVolumeReadback_h
#define VoxelGIVolumeReadback_h

class vtkFloatArray;
class vtkImageData;
class vtkOpenGLRenderWindow;

namespace voxelgi
{
class Composite;
struct VoxelView;

/// Copy volume `volume` (vtkVoxelGIPass::Volumes) of `voxels` into `image`, making their
/// window's context current. False when there is no such volume (yet).
bool ReadVolume(const VoxelView& voxels, int volume, vtkImageData* image);

/// Copy float image `image` (vtkVoxelGIPass::Images) of `composite`, made in `window`, into
/// `pixels` (RGBA).
bool ReadImage(Composite& composite, vtkOpenGLRenderWindow* window, int image, vtkFloatArray* pixels);

}

#endif
