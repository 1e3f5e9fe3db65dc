#include "Composite.h"

#include "ConeTrace.h"
#include "Frame.h"
#include "GBufferPass.h"
#include "GLHelpers.h"
#include "GridView.h"
#include "VoxelGIShaders.h"
#include "StageIds.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtk_glew.h"

namespace voxelgi
{

Composite::Composite(const GBufferPass& gbuffer, const ConeTrace& trace)
  : GBuffer(gbuffer)
  , Trace(trace)
{
}

Composite::~Composite() = default;

bool Composite::Prepare(const Frame& frame, std::string& error)
{
  if (!this->Color)
  {
    this->Color = NewImageTexture(frame.Window, GL_RGBA32F, frame.Width, frame.Height);
    this->Indirect = NewImageTexture(frame.Window, GL_RGBA32F, frame.Width, frame.Height);
    this->Scale = NewImageTexture(frame.Window, GL_RGBA16F, frame.Width, frame.Height);
    this->Add = NewImageTexture(frame.Window, GL_RGBA16F, frame.Width, frame.Height);
  }
  this->Color->Resize(frame.Width, frame.Height);
  this->Indirect->Resize(frame.Width, frame.Height);
  this->Scale->Resize(frame.Width, frame.Height);
  this->Add->Resize(frame.Width, frame.Height);
  return this->Program.BuildOnce(shaders::composite_comp, "composite", error);
}

void Composite::Run(const Frame& frame)
{
  ScopedStage stage(*frame.Clock, stage::Composite);
  vtkTextureObject* indirect = this->Trace.GetIndirect();
  vtkTextureObject* shadowed = this->Trace.GetShadowed();
  GLProgram& p = this->Program;
  p.Use(frame.Window);
  ScopedTextures inputs({ this->GBuffer.GetColor(), this->GBuffer.GetNormal(),
    this->GBuffer.GetAmbient(), this->GBuffer.GetDepth(), indirect, shadowed });
  if (!(inputs.Complete()))
  {
    return;
  }
  float gridFromNDC[16];
  GridFromNDC(frame.Renderer, frame.Grid, gridFromNDC);
  p.SetMat4Array("voxelFromNDC", 1, gridFromNDC);
  float normalToGrid[9];
  NormalToGrid(frame.Renderer, normalToGrid);
  p.SetMat3("normalToGrid", normalToGrid);
  p.SetInt("gbufferColor", this->GBuffer.GetColor()->GetTextureUnit());
  p.SetInt("gbufferNormal", this->GBuffer.GetNormal()->GetTextureUnit());
  p.SetInt("gbufferAmbient", this->GBuffer.GetAmbient()->GetTextureUnit());
  p.SetInt("gbufferDepth", this->GBuffer.GetDepth()->GetTextureUnit());
  p.SetInt("traceIndirect", indirect->GetTextureUnit());
  p.SetInt("traceShadowed", shadowed->GetTextureUnit());
  p.SetVec2("traceSize", static_cast<float>(indirect->GetWidth()),
    static_cast<float>(indirect->GetHeight()));
  p.SetFloat("aoStrength", static_cast<float>(frame.Config.AmbientOcclusionStrength));
  const int view = frame.Config.DebugView;
  p.SetInt("compositeView",
    view >= DEBUG_VIEW_DIRECT ? view - DEBUG_VIEW_DIRECT + 1 : 0);
  BindImage2D(0, this->Color, GL_WRITE_ONLY, GL_RGBA32F);
  BindImage2D(1, this->Indirect, GL_WRITE_ONLY, GL_RGBA32F);
  BindImage2D(2, this->Scale, GL_WRITE_ONLY, GL_RGBA16F);
  BindImage2D(3, this->Add, GL_WRITE_ONLY, GL_RGBA16F);
  p.DispatchImage(frame.Width, frame.Height, 8);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
    GL_TEXTURE_UPDATE_BARRIER_BIT);
}

bool Composite::Read(
  vtkOpenGLRenderWindow* renWin, int image, std::vector<float>& rgba, int& w, int& h)
{
  vtkTextureObject* texture = image == 0 ? this->Color.Get() : this->Indirect.Get();
  if (!texture)
  {
    return false;
  }
  if (!MakeCurrentForReading(renWin))
  {
    return false;
  }
  // GL writes the texture as it holds it: size the buffer from that, never from what
  // vtkTextureObject was last asked for (a resize GL refused keeps the old storage).
  StoredSize(texture, w, h);
  if (w <= 0 || h <= 0 || w != static_cast<int>(texture->GetWidth()) ||
    h != static_cast<int>(texture->GetHeight()))
  {
    return false; // not the image of the last composite
  }
  rgba.resize(static_cast<std::size_t>(w) * h * 4);
  texture->Activate();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, rgba.data());
  texture->Deactivate();
  return true;
}

void Composite::ReleaseGraphicsResources(vtkWindow* window)
{
  for (vtkTextureObject* texture :
    { this->Color.Get(), this->Indirect.Get(), this->Scale.Get(), this->Add.Get() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(window);
    }
  }
  this->Color = this->Indirect = this->Scale = this->Add = nullptr;
  this->Program.Release();
}

}
