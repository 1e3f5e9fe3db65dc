#include "Present.h"

#include "Composite.h"
#include "DebugView.h"
#include "Frame.h"
#include "FramePlan.h"
#include "GBufferPass.h"
#include "VoxelGIShaders.h"
#include "StageIds.h"
#include "TranslucentLighting.h"
#include "VolumeLighting.h"
#include "VoxelBounce.h"

#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

namespace voxelgi
{

namespace
{
/// present.frag in GLSL 3.30 (VTK declares 1.50), whose output index qualifier gives the
/// second colour of dual-source blending (Mesa offers its extension to 1.50 only in
/// compatibility contexts).
const char* PresentSource()
{
  static const std::string source = [] {
    std::string text = shaders::present_frag;
    vtkShaderProgram::Substitute(text, "//VTK::System::Dec", "#version 330 core");
    return text;
  }();
  return source.c_str();
}

/// The renderer's viewport and scissor box while it lives, as VTK's camera pass sets them
/// around all of its steps; the previous ones afterwards.
class RendererViewport
{
public:
  RendererViewport(const Frame& frame, vtkOpenGLState* state)
    : Viewport(state)
    , Scissor(state)
    , ScissorTest(state, GL_SCISSOR_TEST)
  {
    state->vtkglEnable(GL_SCISSOR_TEST);
    state->vtkglViewport(frame.X, frame.Y, frame.Width, frame.Height);
    state->vtkglScissor(frame.X, frame.Y, frame.Width, frame.Height);
  }

private:
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglScissor Scissor;
  vtkOpenGLState::ScopedglEnableDisable ScissorTest;
};
}

Present::Present(const Composite& composite, GBufferPass& gbuffer, const DebugView& debug)
  : Compositor(composite)
  , GBuffer(gbuffer)
  , Debug(debug)
{
}

Present::~Present() = default;

bool Present::Prepare(const Frame& frame, std::string& error)
{
  if (!ReadyQuad(this->Quad, frame.Window, PresentSource()))
  {
    error = "could not build the present program";
    return false;
  }
  return true;
}

void Present::Run(const Frame& frame)
{
  if (frame.Plan.VoxelView)
  {
    ScopedStage stage(*frame.Clock, stage::Present);
    this->Draw(frame, Mode::Over, nullptr, this->Debug.GetImage());
    this->RenderedProps = 0;
    return;
  }
  const bool unchanged = frame.Plan.Trace == TraceWork::Present;
  if (unchanged && this->Unchanged.Holds(frame))
  {
    ScopedStage stage(*frame.Clock, stage::Present);
    this->Unchanged.Restore(frame);
  }
  else
  {
    // VTK's draw into a framebuffer of one sample would repeat a G-buffer drawn apart, unless
    // it draws over colours it keeps (a renderer of a layer above another: its G-buffer holds
    // no background). A G-buffer VTK's draw made comes with VTK's image.
    GLint samples = 0;
    glGetIntegerv(GL_SAMPLES, &samples);
    const Mode mode = this->GBuffer.IsFromVTKDraw() || samples > 1 || frame.Renderer->Transparent()
      ? Mode::Samples
      : Mode::Whole;
    this->OpaqueProps = mode == Mode::Samples ? this->GBuffer.RenderVTK(frame)
                                              : this->GBuffer.GetNumberOfRenderedProps();
    ScopedStage stage(*frame.Clock, stage::Present);
    vtkTextureObject* scale = this->Compositor.GetPresentScale();
    vtkTextureObject* add = this->Compositor.GetPresentAdd();
    if (mode != Mode::Samples || !this->Blend.Run(frame, scale, add, this->GBuffer.GetDepth()))
    {
      this->Draw(frame, mode, scale, add);
    }
    if (unchanged)
    {
      this->Unchanged.Store(frame);
    }
    else
    {
      this->Unchanged.Forget();
    }
  }
  // A copied image counts the props that drew it.
  this->RenderedProps = this->OpaqueProps + this->RenderRemainingSteps(frame);
}

void Present::Draw(const Frame& frame, Mode mode, vtkTextureObject* scale, vtkTextureObject* add)
{
  vtkShaderProgram* program = ReadyQuad(this->Quad, frame.Window, PresentSource());
  vtkTextureObject* depth = mode != Mode::Over ? this->GBuffer.GetDepth() : nullptr;
  vtkTextureObject* color = mode == Mode::Whole ? this->GBuffer.GetColor() : nullptr;
  if (!program || !add || (mode != Mode::Over && !(scale && depth)) ||
    (mode == Mode::Whole && !color))
  {
    return;
  }
  ScopedTextures inputs({ add, scale, depth, color });
  if (!(inputs.Complete()))
  {
    return;
  }
  program->SetUniformi("presentAdd", add->GetTextureUnit());
  program->SetUniformi("presentScale", (scale ? scale : add)->GetTextureUnit());
  program->SetUniformi("gbufferDepth", (depth ? depth : add)->GetTextureUnit());
  program->SetUniformi("gbufferColor", (color ? color : add)->GetTextureUnit());
  program->SetUniformi("presentMode", static_cast<int>(mode));
  vtkOpenGLState* ostate = frame.Window->GetState();
  RendererViewport viewport(frame, ostate);
  vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(ostate);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  if (mode == Mode::Whole)
  {
    // Every pixel of the viewport, with its depth: VTK's image as its draw would leave it.
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglDepthFunc(GL_ALWAYS);
    ostate->vtkglDepthMask(GL_TRUE);
  }
  else
  {
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendEquation(GL_FUNC_ADD);
    // Each sample: add + scale * sample (alpha: 0 + 1 * alpha).
    ostate->vtkglBlendFuncSeparate(GL_ONE, GL_SRC1_COLOR, GL_ONE, GL_SRC1_ALPHA);
    ostate->vtkglDepthFunc(GL_GEQUAL);
    ostate->vtkglDepthMask(GL_FALSE);
  }
  this->Quad->Render();
}

int Present::RenderRemainingSteps(const Frame& frame)
{
  auto* steps = vtkRenderStepsPass::SafeDownCast(frame.Delegate);
  if (!steps)
  {
    return 0;
  }
  vtkOpenGLState* ostate = frame.Window->GetState();
  vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  // 2D props place and scale themselves by the viewport; the camera pass that drew the
  // opaque steps has put the previous one back.
  RendererViewport viewport(frame, ostate);
  int rendered = 0;
  // Translucent geometry as the renderer alone draws it: with its order-independent
  // translucency or depth peeling as its settings say (the steps pass's own translucent
  // step blends in drawing order).
  vtkRenderer* renderer = frame.Renderer;
  if (steps->GetTranslucentPass())
  {
    const int before = renderer->GetNumberOfPropsRendered();
    this->Translucent->Draw(frame, [renderer]() { renderer->DeviceRenderTranslucentPolygonalGeometry(); });
    rendered += renderer->GetNumberOfPropsRendered() - before;
  }
  // VTK applies FXAA here (before volumes and overlays) only when a renderer has no pass.
  auto* openGLRenderer = vtkOpenGLRenderer::SafeDownCast(renderer);
  if (renderer->GetUseFXAA() && openGLRenderer)
  {
    if (!this->FXAA)
    {
      this->FXAA = vtkSmartPointer<vtkOpenGLFXAAFilter>::New();
    }
    if (renderer->GetFXAAOptions())
    {
      this->FXAA->UpdateConfiguration(renderer->GetFXAAOptions());
    }
    this->FXAA->Execute(openGLRenderer);
  }
  // Volumes with the indirect light the scene sends them.
  if (vtkRenderPass* volumetric = steps->GetVolumetricPass())
  {
    rendered += this->Volumes->Draw(
      frame, volumetric, frame.Bounce ? frame.Bounce->GetIncident() : nullptr);
  }
  for (vtkRenderPass* pass : { steps->GetOverlayPass(), steps->GetPostProcessPass() })
  {
    if (pass)
    {
      pass->Render(frame.State);
      rendered += pass->GetNumberOfRenderedProps();
    }
  }
  return rendered;
}

void Present::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
  this->Blend.ReleaseGraphicsResources();
  this->Unchanged.ReleaseGraphicsResources(window);
  if (this->FXAA)
  {
    this->FXAA->ReleaseGraphicsResources();
    this->FXAA = nullptr;
  }
  this->Volumes->ReleaseGraphicsResources(window);
  this->Translucent->ReleaseGraphicsResources(window);
}

}
