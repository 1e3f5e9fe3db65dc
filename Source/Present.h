/**
 * Present stage (present.frag): draws an RGBA8 image (the composite with the G-buffer's depth,
 * or, in a voxel debug view, the debug image over VTK's image) into the currently bound
 * framebuffer at the frame's viewport, so that VTK's translucent, volume and overlay steps
 * that follow depth-test against the scene. The one full-screen fragment pass of the pipeline: the framebuffer (and its
 * depth) may be VTK's, ParaView's or a Qt widget's. Then VTK's own remaining steps draw as VTK
 * would draw them.
 */
#ifndef VoxelGIPresent_h
#define VoxelGIPresent_h

#include <memory>

#include <string>

class vtkOpenGLQuadHelper;
class vtkTextureObject;
class vtkWindow;

namespace voxelgi
{
struct Frame;
class Composite;
class DebugView;
class GBufferPass;

class Present
{
public:
  Present(const Composite& composite, const GBufferPass& gbuffer, const DebugView& debug);
  ~Present();

  bool Prepare(const Frame& frame, std::string& error);
  /// Draw the frame's image. After the composite, the steps of a vtkRenderStepsPass
  /// delegate that follow its opaque one (translucent, volumetric, overlay, post-process)
  /// draw, depth-tested against the scene (not timed: plain VTK draws them too).
  void Run(const Frame& frame);
  /// The number of props VTK's remaining steps rendered in the last Run.
  int GetNumberOfRenderedProps() const { return this->RenderedProps; }
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  /// Draw `image`; write `depth` (may be null: the framebuffer's depth is kept).
  void Draw(const Frame& frame, vtkTextureObject* image, vtkTextureObject* depth);
  int RenderRemainingSteps(const Frame& frame);

  const Composite& Compositor;
  const GBufferPass& GBuffer;
  const DebugView& Debug;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  int RenderedProps = 0;
};

}

#endif
