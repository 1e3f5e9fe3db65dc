/**
 * Present stage (present.frag, present_samples.comp): VTK draws its camera, lights and opaque
 * steps into its own framebuffer as it would without the pass (its multisampling, depth and
 * look kept, through the G-buffer's shaders), then the composite is blended into each of its
 * samples (s * scale + add, for the samples of the G-buffer's surface, so that edges keep
 * VTK's coverage: a dispatch, PresentSamples, where the framebuffer's attachments are
 * textures, else a depth-tested quad), or, in a voxel debug view, the debug image is drawn
 * over VTK's image. A framebuffer of one sample takes the G-buffer's own draw of those steps
 * instead (its colour and depth, with the composite applied): VTK's draw would repeat it. A
 * frame that shows the last image again copies it back (FrameCopy) where the framebuffer
 * allows. The framebuffer may be VTK's, ParaView's or a Qt widget's. Then VTK's own remaining
 * steps draw as VTK would draw them, with the renderer's FXAA (vtkRenderer::UseFXAA) before
 * volumes and overlays, where VTK applies it; the volumes in the voxels and the translucent
 * surfaces add the indirect light that reaches them (VolumeLighting, TranslucentLighting).
 */
#ifndef VoxelGIPresent_h
#define VoxelGIPresent_h

#include "FrameCopy.h"
#include "PresentSamples.h"

#include "vtkNew.h"          // for vtkNew
#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <memory>

#include <string>

class vtkOpenGLFXAAFilter;
class vtkOpenGLQuadHelper;
class vtkTextureObject;
class vtkWindow;

namespace voxelgi
{
struct Frame;
class Composite;
class DebugView;
class GBufferPass;
class TranslucentLighting;
class VolumeLighting;

class Present
{
public:
  Present(const Composite& composite, GBufferPass& gbuffer, const DebugView& debug);
  ~Present();

  bool Prepare(const Frame& frame, std::string& error);
  /// Draw the frame's image: VTK's opaque steps (not timed: plain VTK draws them too), the
  /// composite blended in, then the steps of a vtkRenderStepsPass delegate that follow its
  /// opaque one (translucent, volumetric, overlay, post-process; not timed either). A voxel
  /// debug view: the debug image over VTK's image (drawn by the pass).
  void Run(const Frame& frame);
  /// The number of props VTK's steps rendered in the last Run.
  int GetNumberOfRenderedProps() const { return this->RenderedProps; }
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  /// How Draw puts its image into the framebuffer (present.frag's modes).
  enum class Mode
  {
    Samples = 0, ///< scale and add blended into VTK's samples, depth-tested (VTK drew them)
    Over = 1,    ///< add as it is over VTK's image (a voxel debug view)
    Whole = 2    ///< VTK's colour from the G-buffer, scaled and added to, with its depth
  };
  void Draw(const Frame& frame, Mode mode, vtkTextureObject* scale, vtkTextureObject* add);
  int RenderRemainingSteps(const Frame& frame);

  const Composite& Compositor;
  GBufferPass& GBuffer;
  const DebugView& Debug;
  vtkNew<VolumeLighting> Volumes; // VTK's volumes lit by GI
  vtkNew<TranslucentLighting> Translucent; // VTK's translucent surfaces lit by GI
  PresentSamples Blend; // the composite into VTK's samples, where its framebuffer allows
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  FrameCopy Unchanged; // the last presented image, for frames that show it again
  vtkSmartPointer<vtkOpenGLFXAAFilter> FXAA;
  int RenderedProps = 0;
  int OpaqueProps = 0; // drawn by VTK's opaque steps the last time they drew
};

}

#endif
