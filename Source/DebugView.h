/**
 * Debug view stage: draws the voxel volumes as the image, seen through the renderer's
 * camera, so a user can check what was voxelized (albedo, normal or emission).
 */
#ifndef VoxelGIVoxelDebugView_h
#define VoxelGIVoxelDebugView_h

#include <memory>

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkWindow;

namespace voxelgi
{
class Voxelizer;
class Volume3D;
struct VoxelGrid;

class VoxelDebugView
{
public:
  VoxelDebugView();
  ~VoxelDebugView();

  /// Draw over the renderer's viewport in the currently bound framebuffer.
  /// `view`: 1 albedo, 2 normal, 3 emission, 4 radiance.
  void Render(vtkRenderer* renderer, const VoxelGrid& grid, const Voxelizer& voxels,
    const Volume3D& radiance, int view);
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
};

}

#endif
