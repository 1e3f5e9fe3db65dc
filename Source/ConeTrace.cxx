#include "ConeTrace.h"

#include "Frame.h"
#include "GBufferPass.h"
#include "GridView.h"
#include "LightVoxels.h"
#include "ShadowMaps.h"
#include "VoxelGIShaders.h"
#include "VoxelMipmap.h"
#include "StageIds.h"
#include "TraceScale.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

namespace voxelgi
{

namespace
{
constexpr int Tile = 8; // cone_trace.comp's local size
}

ConeTrace::ConeTrace(const GBufferPass& gbuffer)
  : GBuffer(gbuffer)
{
}

bool ConeTrace::Prepare(const Frame& frame, std::string& error)
{
  const double scale =
    TraceScale(frame.Config.TraceResolution, frame.Config.MaxTraceMegapixels, frame.Width, frame.Height);
  const int tw = std::max(1, static_cast<int>(std::ceil(frame.Width * scale)));
  const int th = std::max(1, static_cast<int>(std::ceil(frame.Height * scale)));
  for (TraceImages& images : this->History)
  {
    if (!images.Indirect)
    {
      images.Indirect = NewImageTexture(frame.Window, GL_RGBA16F, tw, th);
      images.Shadowed = NewImageTexture(frame.Window, GL_RGBA16F, tw, th);
      images.Surface = NewImageTexture(frame.Window, GL_RG32F, tw, th, 2);
      this->HistoryValid = false;
    }
    if (images.Indirect->GetWidth() != static_cast<unsigned int>(tw) ||
      images.Indirect->GetHeight() != static_cast<unsigned int>(th))
    {
      images.Indirect->Resize(tw, th);
      images.Shadowed->Resize(tw, th);
      images.Surface->Resize(tw, th);
      this->HistoryValid = false;
    }
  }
  this->Cones.Set(frame.Config, frame.Grid.Resolution);
  // The shadow-map variant is compiled only when a scene uses it.
  this->WithShadowMaps = frame.Shadows && frame.Shadows->HasMaps() && frame.Config.ConeShadows;
  return this->Program.BuildOnce(shaders::cone_trace_comp, "cone tracing", error,
    this->WithShadowMaps ? "#define VOXELGI_SHADOW_MAPS\n" : "");
}

void ConeTrace::SetUniforms(const Frame& frame)
{
  GLProgram& p = this->Program;
  const Settings& config = frame.Config;
  // NDC -> grid coordinates (composed in double, see GridFromNDC) and view normals -> grid.
  // Kept for the next frame's reprojection (after SetHistoryUniforms used the last ones).
  GridFromNDC(frame.Renderer, frame.Grid, this->PreviousGridFromNDC, this->PreviousNDCFromGrid);
  p.SetMat4Array("voxelFromNDC", 1, this->PreviousGridFromNDC);
  float normalToGrid[9];
  NormalToGrid(frame.Renderer, normalToGrid);
  p.SetMat3("normalToGrid", normalToGrid);
  p.SetInt("gbufferNormal", this->GBuffer.GetNormal()->GetTextureUnit());
  p.SetInt("gbufferMaterial", this->GBuffer.GetMaterial()->GetTextureUnit());
  p.SetInt("gbufferDepth", this->GBuffer.GetDepth()->GetTextureUnit());
  p.SetVec3Array("coneDirections", this->Cones.Count, this->Cones.Directions);
  p.SetInt("coneCount", this->Cones.Count);
  p.SetFloat("diffuseTanHalf", this->Cones.TanHalf);
  p.SetFloat("maxDistance", this->Cones.MaxDistance);
  p.SetFloat("startOffset", static_cast<float>(config.ConeStartOffset));
  p.SetFloat("indirectIntensity", static_cast<float>(config.IndirectIntensity));
  p.SetFloat("specularIntensity", static_cast<float>(config.SpecularIntensity));
  // No specular material in the scene: no specular cone.
  p.SetInt("specularCone", config.SpecularCone && frame.AnySpecular ? 1 : 0);
  p.SetFloat("aoFalloff", static_cast<float>(config.AmbientOcclusionFalloff));
  p.SetInt("coneShadows", config.ConeShadows ? 1 : 0);
  p.SetFloat("shadowTanHalf",
    static_cast<float>(std::tan(vtkMath::RadiansFromDegrees(0.5 * config.ShadowConeAperture))));
}

void ConeTrace::SetHistoryUniforms(const Frame& frame, bool reuse)
{
  GLProgram& p = this->Program;
  p.SetInt("temporalPhase", reuse ? this->Phase : -1);
  p.SetMat4Array("previousGridFromNDC", 1, this->PreviousGridFromNDC);
  p.SetMat4Array("previousNDCFromGrid", 1, this->PreviousNDCFromGrid);
  p.SetVec4("previousEye", this->PreviousEye);
  this->Phase = reuse ? (this->Phase + 1) % 4 : 0;
  // Remember this frame's eye in grid coordinates, or the direction of view of a parallel
  // projection (w 0).
  vtkCamera* camera = frame.Renderer->GetActiveCamera();
  double eye[3];
  camera->GetPosition(eye);
  double direction[3];
  camera->GetDirectionOfProjection(direction);
  const bool parallel = camera->GetParallelProjection() != 0;
  for (int a = 0; a < 3; ++a)
  {
    this->PreviousEye[a] = static_cast<float>(
      parallel ? direction[a] : (eye[a] - frame.Grid.Origin[a]) / frame.Grid.VoxelSize);
  }
  this->PreviousEye[3] = parallel ? 0.0f : 1.0f;
}

void ConeTrace::Run(const Frame& frame)
{
  ScopedStage stage(*frame.Clock, stage::ConeTrace);
  this->Current = 1 - this->Current;
  const TraceImages& now = this->History[this->Current];
  const TraceImages& before = this->History[1 - this->Current];
  const int width = now.Indirect->GetWidth();
  const int height = now.Indirect->GetHeight();
  // Without room for the list of pixels to trace again, every pixel is traced.
  const bool reuse = frame.Config.TemporalReuse && frame.Plan.Trace == TraceWork::CameraOnly &&
    this->HistoryValid &&
    this->RetraceList.Allocate(sizeof(unsigned int) * (4 + static_cast<std::size_t>(width) * height));
  GLProgram& p = this->Program;
  p.Use(frame.Window);
  SamplerBindings samplers(frame.Window);
  SetConeTracingSamplers(
    p, samplers, frame.Lighting->GetRadiance(), *frame.Mipmap, 0.0f, this->Cones.StepFactor);
  if (this->WithShadowMaps)
  {
    frame.Shadows->Bind(p, samplers);
  }
  ScopedTextures inputs({ this->GBuffer.GetNormal(), this->GBuffer.GetMaterial(),
    this->GBuffer.GetDepth(), before.Indirect, before.Shadowed, before.Surface });
  this->HistoryValid = false;
  this->Reused = false;
  if (!(samplers.Complete() && inputs.Complete()))
  {
    return;
  }
  p.SetInt("previousIndirect", before.Indirect->GetTextureUnit());
  p.SetInt("previousShadowed", before.Shadowed->GetTextureUnit());
  p.SetInt("previousSurface", before.Surface->GetTextureUnit());
  this->SetHistoryUniforms(frame, reuse);
  this->SetUniforms(frame);
  BindImage2D(0, now.Indirect, GL_WRITE_ONLY, GL_RGBA16F);
  BindImage2D(1, now.Shadowed, GL_WRITE_ONLY, GL_RGBA16F);
  BindImage2D(2, now.Surface, GL_WRITE_ONLY, GL_RG32F);
  if (reuse)
  {
    const unsigned int emptyList[4] = { 0, 1, 1, 0 }; // no group yet; 1 x 1 in y and z
    this->RetraceList.Upload(emptyList, sizeof(emptyList));
    this->RetraceList.Bind(VOXELGI_RETRACE_LIST_BINDING);
  }
  p.SetInt("retracePass", 0);
  p.DispatchImage(width, height, Tile);
  if (reuse)
  {
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    p.Use(frame.Window);
    p.SetInt("retracePass", 1);
    p.DispatchIndirect(this->RetraceList);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  this->HistoryValid = true;
  this->Reused = reuse;
}

void ConeTrace::ReleaseGraphicsResources(vtkWindow* window)
{
  for (TraceImages& images : this->History)
  {
    for (vtkTextureObject* texture :
      { images.Indirect.Get(), images.Shadowed.Get(), images.Surface.Get() })
    {
      if (texture)
      {
        texture->ReleaseGraphicsResources(window);
      }
    }
    images = TraceImages();
  }
  this->HistoryValid = false;
  this->Reused = false;
  this->RetraceList.Release();
  this->Program.Release();
}

}
