#include "ConeTracer.h"

#include "GBuffer.h"
#include "VoxelGIShaders.h"
#include "GridView.h"
#include "VoxelGrid.h"
#include "VoxelLighting.h"
#include "VoxelLights.h"
#include "VoxelMipmap.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

namespace voxelgi
{

namespace
{
// Build the quad program on first use, make it current afterwards.
vtkShaderProgram* ReadyQuad(
  std::unique_ptr<vtkOpenGLQuadHelper>& quad, vtkOpenGLRenderWindow* renWin, const char* fragment)
{
  if (!quad)
  {
    quad.reset(new vtkOpenGLQuadHelper(renWin,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fragment, ""));
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  return (quad->Program && quad->Program->GetCompiled()) ? quad->Program : nullptr;
}

vtkSmartPointer<vtkTextureObject> NewFloatTexture(vtkOpenGLRenderWindow* renWin, int w, int h)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(renWin);
  texture->SetInternalFormat(GL_RGBA32F);
  texture->SetFormat(GL_RGBA);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->Allocate2D(w, h, 4, VTK_FLOAT);
  return texture;
}
}

ConeTracer::ConeTracer() = default;
ConeTracer::~ConeTracer() = default;

void ConeTracer::Trace(vtkRenderer* renderer, const VoxelGrid& grid, const GBuffer& gbuffer,
  const VoxelLighting& lighting, const VoxelMipmap& mips, const ConeSettings& cones,
  const TraceSettings& settings)
{
  auto* renWin = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  const int w = gbuffer.Color->GetWidth();
  const int h = gbuffer.Color->GetHeight();
  if (!this->Framebuffer)
  {
    this->Composite = NewFloatTexture(renWin, w, h);
    this->Indirect = NewFloatTexture(renWin, w, h);
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Framebuffer->SetContext(renWin);
  }
  this->Composite->Resize(w, h);
  this->Indirect->Resize(w, h);

  vtkShaderProgram* program = ReadyQuad(this->TraceQuad, renWin, shaders::cone_trace_frag);
  if (!program)
  {
    return;
  }
  glUniformBlockBinding(program->GetHandle(),
    glGetUniformBlockIndex(program->GetHandle(), "VoxelLightBlock"), VoxelLights::Binding);

  // NDC -> grid coordinates (composed in double, see GridFromNDC) and view normals -> grid.
  float gridFromNDC[16];
  GridFromNDC(renderer, grid, gridFromNDC);
  program->SetUniformMatrix4x4("voxelFromNDC", gridFromNDC);
  vtkMatrix4x4* view = renderer->GetActiveCamera()->GetViewTransformMatrix();
  float normalToGrid[9];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      // inverse of the rotation = its transpose; GLSL matrices are column-major
      normalToGrid[c * 3 + r] = static_cast<float>(view->GetElement(c, r));
    }
  }
  program->SetUniformMatrix3x3("normalToGrid", normalToGrid);

  SamplerBindings samplers(renWin);
  SetConeTracingSamplers(samplers, lighting.Radiance, mips, 0.0f, cones.StepFactor,
    [program](const char* name, auto value) {
      if constexpr (std::is_same_v<decltype(value), int>)
      {
        program->SetUniformi(name, value);
      }
      else
      {
        program->SetUniformf(name, value);
      }
    });
  gbuffer.Color->Activate();
  gbuffer.Normal->Activate();
  gbuffer.Material->Activate();
  gbuffer.Depth->Activate();
  program->SetUniformi("gbufferColor", gbuffer.Color->GetTextureUnit());
  program->SetUniformi("gbufferNormal", gbuffer.Normal->GetTextureUnit());
  program->SetUniformi("gbufferMaterial", gbuffer.Material->GetTextureUnit());
  program->SetUniformi("gbufferDepth", gbuffer.Depth->GetTextureUnit());
  program->SetUniform3fv("coneDirections", cones.Count, cones.Directions);
  program->SetUniformi("coneCount", cones.Count);
  program->SetUniformf("diffuseTanHalf", cones.TanHalf);
  program->SetUniformf("maxDistance", cones.MaxDistance);
  program->SetUniformf("startOffset", settings.StartOffset);
  program->SetUniformf("indirectIntensity", settings.IndirectIntensity);
  program->SetUniformf("specularIntensity", settings.SpecularIntensity);
  program->SetUniformi("specularCone", settings.SpecularCone ? 1 : 0);
  program->SetUniformf("aoStrength", settings.AOStrength);
  program->SetUniformf("aoFalloff", settings.AOFalloff);
  program->SetUniformi("coneShadows", settings.ConeShadows ? 1 : 0);
  program->SetUniformf("shadowTanHalf", settings.ShadowTanHalf);
  program->SetUniformi("compositeView", settings.View);

  this->Framebuffer->SaveCurrentBindingsAndBuffers();
  this->Framebuffer->Bind();
  this->Framebuffer->AddColorAttachment(0, this->Composite);
  this->Framebuffer->AddColorAttachment(1, this->Indirect);
  this->Framebuffer->ActivateDrawBuffers(2);
  this->Framebuffer->StartNonOrtho(w, h);
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglViewport viewport(ostate);
  vtkOpenGLState::ScopedglScissor scissor(ostate);
  vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
  ostate->vtkglViewport(0, 0, w, h);
  ostate->vtkglScissor(0, 0, w, h);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_BLEND);
  this->TraceQuad->Render();
  this->Framebuffer->UnBind();
  this->Framebuffer->RestorePreviousBindingsAndBuffers();

  gbuffer.Depth->Deactivate();
  gbuffer.Material->Deactivate();
  gbuffer.Normal->Deactivate();
  gbuffer.Color->Deactivate();
}

void ConeTracer::Present(
  vtkOpenGLRenderWindow* renWin, const GBuffer& gbuffer, int x, int y, int w, int h)
{
  vtkShaderProgram* program = ReadyQuad(this->PresentQuad, renWin, shaders::present_frag);
  if (!program || !this->Composite)
  {
    return;
  }
  this->Composite->Activate();
  gbuffer.Depth->Activate();
  program->SetUniformi("compositeColor", this->Composite->GetTextureUnit());
  program->SetUniformi("gbufferDepth", gbuffer.Depth->GetTextureUnit());
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(ostate);
  ostate->vtkglViewport(x, y, w, h);
  ostate->vtkglScissor(x, y, w, h);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  this->PresentQuad->Render();
  gbuffer.Depth->Deactivate();
  this->Composite->Deactivate();
}

bool ConeTracer::Read(
  vtkOpenGLRenderWindow* renWin, int image, std::vector<float>& rgba, int& w, int& h)
{
  vtkTextureObject* texture = image == 0 ? this->Composite.Get() : this->Indirect.Get();
  if (!texture)
  {
    return false;
  }
  renWin->MakeCurrent();
  w = texture->GetWidth();
  h = texture->GetHeight();
  rgba.resize(static_cast<std::size_t>(w) * h * 4);
  texture->Activate();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, rgba.data());
  texture->Deactivate();
  return true;
}

void ConeTracer::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto* quad : { &this->TraceQuad, &this->PresentQuad })
  {
    if (*quad)
    {
      (*quad)->ReleaseGraphicsResources(window);
      quad->reset();
    }
  }
  for (vtkTextureObject* texture : { this->Composite.Get(), this->Indirect.Get() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(window);
    }
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  this->Framebuffer = nullptr;
  this->Composite = this->Indirect = nullptr;
}

}
