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

#include <algorithm>
#include <cmath>
#include <type_traits>

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

vtkSmartPointer<vtkTextureObject> NewFloatTexture(
  vtkOpenGLRenderWindow* renWin, int w, int h, int internalFormat)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(renWin);
  texture->SetInternalFormat(internalFormat);
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
  const int tw = std::max(1, static_cast<int>(std::ceil(w * settings.Scale)));
  const int th = std::max(1, static_cast<int>(std::ceil(h * settings.Scale)));
  if (!this->Framebuffer)
  {
    this->TraceIndirect = NewFloatTexture(renWin, tw, th, GL_RGBA16F);
    this->TraceShadowed = NewFloatTexture(renWin, tw, th, GL_RGBA16F);
    this->Composite = NewFloatTexture(renWin, w, h, GL_RGBA32F);
    this->Indirect = NewFloatTexture(renWin, w, h, GL_RGBA32F);
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Framebuffer->SetContext(renWin);
  }
  this->TraceIndirect->Resize(tw, th);
  this->TraceShadowed->Resize(tw, th);
  this->Composite->Resize(w, h);
  this->Indirect->Resize(w, h);

  vtkShaderProgram* trace = ReadyQuad(this->TraceQuad, renWin, shaders::cone_trace_frag);
  if (!trace)
  {
    return;
  }
  glUniformBlockBinding(trace->GetHandle(),
    glGetUniformBlockIndex(trace->GetHandle(), "VoxelLightBlock"), VoxelLights::Binding);

  // NDC -> grid coordinates (composed in double, see GridFromNDC) and view normals -> grid.
  float gridFromNDC[16];
  GridFromNDC(renderer, grid, gridFromNDC);
  trace->SetUniformMatrix4x4("voxelFromNDC", gridFromNDC);
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
  trace->SetUniformMatrix3x3("normalToGrid", normalToGrid);

  SamplerBindings samplers(renWin);
  SetConeTracingSamplers(samplers, lighting.Radiance, mips, 0.0f, cones.StepFactor,
    [trace](const char* name, auto value) {
      if constexpr (std::is_same_v<decltype(value), int>)
      {
        trace->SetUniformi(name, value);
      }
      else
      {
        trace->SetUniformf(name, value);
      }
    });
  gbuffer.Color->Activate();
  gbuffer.Normal->Activate();
  gbuffer.Material->Activate();
  gbuffer.Depth->Activate();
  trace->SetUniformi("gbufferNormal", gbuffer.Normal->GetTextureUnit());
  trace->SetUniformi("gbufferMaterial", gbuffer.Material->GetTextureUnit());
  trace->SetUniformi("gbufferDepth", gbuffer.Depth->GetTextureUnit());
  trace->SetUniform3fv("coneDirections", cones.Count, cones.Directions);
  trace->SetUniformi("coneCount", cones.Count);
  trace->SetUniformf("diffuseTanHalf", cones.TanHalf);
  trace->SetUniformf("maxDistance", cones.MaxDistance);
  trace->SetUniformf("startOffset", settings.StartOffset);
  trace->SetUniformf("indirectIntensity", settings.IndirectIntensity);
  trace->SetUniformf("specularIntensity", settings.SpecularIntensity);
  trace->SetUniformi("specularCone", settings.SpecularCone ? 1 : 0);
  trace->SetUniformf("aoFalloff", settings.AOFalloff);
  trace->SetUniformi("coneShadows", settings.ConeShadows ? 1 : 0);
  trace->SetUniformf("shadowTanHalf", settings.ShadowTanHalf);

  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglViewport viewport(ostate);
  vtkOpenGLState::ScopedglScissor scissor(ostate);
  vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_BLEND);
  this->Framebuffer->SaveCurrentBindingsAndBuffers();
  this->Framebuffer->Bind();

  // Trace at the trace resolution.
  this->Framebuffer->AddColorAttachment(0, this->TraceIndirect);
  this->Framebuffer->AddColorAttachment(1, this->TraceShadowed);
  this->Framebuffer->ActivateDrawBuffers(2);
  this->Framebuffer->StartNonOrtho(tw, th);
  ostate->vtkglViewport(0, 0, tw, th);
  ostate->vtkglScissor(0, 0, tw, th);
  this->TraceQuad->Render();

  // Composite at the image's resolution.
  vtkShaderProgram* composite = ReadyQuad(this->CompositeQuad, renWin, shaders::composite_frag);
  if (composite)
  {
    this->TraceIndirect->Activate();
    this->TraceShadowed->Activate();
    composite->SetUniformMatrix4x4("voxelFromNDC", gridFromNDC);
    composite->SetUniformi("gbufferColor", gbuffer.Color->GetTextureUnit());
    composite->SetUniformi("gbufferNormal", gbuffer.Normal->GetTextureUnit());
    composite->SetUniformi("gbufferDepth", gbuffer.Depth->GetTextureUnit());
    composite->SetUniformi("traceIndirect", this->TraceIndirect->GetTextureUnit());
    composite->SetUniformi("traceShadowed", this->TraceShadowed->GetTextureUnit());
    const float traceSize[2] = { static_cast<float>(tw), static_cast<float>(th) };
    composite->SetUniform2f("traceSize", traceSize);
    composite->SetUniformf("aoStrength", settings.AOStrength);
    composite->SetUniformi("compositeView", settings.View);
    this->Framebuffer->AddColorAttachment(0, this->Composite);
    this->Framebuffer->AddColorAttachment(1, this->Indirect);
    this->Framebuffer->ActivateDrawBuffers(2);
    this->Framebuffer->StartNonOrtho(w, h);
    ostate->vtkglViewport(0, 0, w, h);
    ostate->vtkglScissor(0, 0, w, h);
    this->CompositeQuad->Render();
    this->TraceShadowed->Deactivate();
    this->TraceIndirect->Deactivate();
  }
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
  for (auto* quad : { &this->TraceQuad, &this->CompositeQuad, &this->PresentQuad })
  {
    if (*quad)
    {
      (*quad)->ReleaseGraphicsResources(window);
      quad->reset();
    }
  }
  for (vtkTextureObject* texture : { this->TraceIndirect.Get(), this->TraceShadowed.Get(),
         this->Composite.Get(), this->Indirect.Get() })
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
  this->TraceIndirect = this->TraceShadowed = this->Composite = this->Indirect = nullptr;
}

}
