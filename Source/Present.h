/**
 * Present stage (present.frag): draws an RGBA8 image (the composite, or a debug view) into the
 * currently bound framebuffer at the frame's viewport, with the scene depth where one is
 * given, so that VTK's translucent, volume and overlay steps that follow depth-test against
 * the scene. The one full-screen fragment pass of the pipeline: the framebuffer (and its
 * depth) may be VTK's, ParaView's or a Qt widget's. Then VTK's own remaining steps draw as VTK
 * would draw them.
 */
#ifndef VoxelGIPresent_h
#define VoxelGIPresent_h

#include <memory>

class vtkOpenGLQuadHelper;
class vtkTextureObject;
class vtkWindow;

namespace voxelgi
{
struct Frame;

class Present
{
public:
  Present();
  ~Present();

  /// Draw `image`; write `depth` (may be null: the framebuffer's depth is kept).
  void Run(const Frame& frame, vtkTextureObject* image, vtkTextureObject* depth);
  /// After Run: the steps of a vtkRenderStepsPass delegate that follow its opaque one
  /// (translucent, volumetric, overlay, post-process), depth-tested against the scene.
  /// Returns the number of props they rendered.
  int RenderRemainingSteps(const Frame& frame);
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
};

}

#endif
