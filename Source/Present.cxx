#include "Present.h"

#include "Composite.h"
#include "DebugView.h"
#include "Frame.h"
#include "GBufferPass.h"
#include "VoxelGIShaders.h"
#include "StageIds.h"

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

namespace voxelgi
{

Present::Present(const Composite& composite, const GBufferPass& gbuffer, const DebugView& debug)
  : Compositor(composite)
  , GBuffer(gbuffer)
  , Debug(debug)
{
}

Present::~Present() = default;

bool Present::Prepare(const Frame& frame, std::string& error)
{
  if (!ReadyQuad(this->Quad, frame.Window, shaders::present_frag))
  {
    error = "could not build the present program";
    return false;
  }
  return true;
}

void Present::Run(const Frame& frame)
{
  this->RenderedProps = 0;
  if (frame.Plan.VoxelView)
  {
    ScopedStage stage(*frame.Clock, stage::Present);
    this->Draw(frame, this->Debug.GetImage(), nullptr);
    return;
  }
  {
    ScopedStage stage(*frame.Clock, stage::Present);
    this->Draw(frame, this->Compositor.GetDisplay(), this->GBuffer.GetDepth());
  }
  this->RenderedProps = this->RenderRemainingSteps(frame);
}

void Present::Draw(const Frame& frame, vtkTextureObject* image, vtkTextureObject* depth)
{
  vtkShaderProgram* program = ReadyQuad(this->Quad, frame.Window, shaders::present_frag);
  if (!program || !image)
  {
    return;
  }
  // Without a depth image, depth writes are masked: the shader's depth output is discarded.
  ScopedTextures inputs({ image, depth });
  if (!(inputs.Complete()))
  {
    return;
  }
  program->SetUniformi("compositeColor", image->GetTextureUnit());
  program->SetUniformi("gbufferDepth", (depth ? depth : image)->GetTextureUnit());
  vtkOpenGLState* ostate = frame.Window->GetState();
  vtkOpenGLState::ScopedglViewport viewport(ostate);
  vtkOpenGLState::ScopedglScissor scissor(ostate);
  vtkOpenGLState::ScopedglEnableDisable scissorTest(ostate, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  ostate->vtkglViewport(frame.X, frame.Y, frame.Width, frame.Height);
  ostate->vtkglScissor(frame.X, frame.Y, frame.Width, frame.Height);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(depth ? GL_TRUE : GL_FALSE);
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
  int rendered = 0;
  // Translucent geometry as the renderer alone draws it: with its order-independent
  // translucency or depth peeling as its settings say (the steps pass's own translucent
  // step blends in drawing order).
  vtkRenderer* renderer = frame.Renderer;
  if (steps->GetTranslucentPass())
  {
    const int before = renderer->GetNumberOfPropsRendered();
    renderer->DeviceRenderTranslucentPolygonalGeometry();
    rendered += renderer->GetNumberOfPropsRendered() - before;
  }
  for (vtkRenderPass* pass :
    { steps->GetVolumetricPass(), steps->GetOverlayPass(), steps->GetPostProcessPass() })
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
}

}
