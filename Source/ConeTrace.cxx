#include "ConeTrace.h"

#include "Frame.h"
#include "GBufferPass.h"
#include "GridView.h"
#include "LightVoxels.h"
#include "VoxelGIShaders.h"
#include "VoxelMipmap.h"
#include "vtkVoxelGIPass.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
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

ConeTrace::ConeTrace(const GBufferPass& gbuffer, const LightVoxels& lighting, const VoxelMipmap& mipmap)
  : GBuffer(gbuffer)
  , Lighting(lighting)
  , Mipmap(mipmap)
{
}

bool ConeTrace::Prepare(const Frame& frame, std::string& error)
{
  const double scale = frame.Config.TraceResolution;
  const int tw = std::max(1, static_cast<int>(std::ceil(frame.Width * scale)));
  const int th = std::max(1, static_cast<int>(std::ceil(frame.Height * scale)));
  if (!this->Indirect)
  {
    this->Indirect = NewImageTexture(frame.Window, GL_RGBA16F, tw, th);
    this->Shadowed = NewImageTexture(frame.Window, GL_RGBA16F, tw, th);
  }
  this->Indirect->Resize(tw, th);
  this->Shadowed->Resize(tw, th);
  this->Cones.Set(frame.Config, frame.Grid.Resolution);
  return this->Program.BuildOnce(shaders::cone_trace_comp, "cone tracing", error);
}

void ConeTrace::SetUniforms(const Frame& frame)
{
  ComputeProgram& p = this->Program;
  const Settings& config = frame.Config;
  // NDC -> grid coordinates (composed in double, see GridFromNDC) and view normals -> grid.
  float gridFromNDC[16];
  GridFromNDC(frame.Renderer, frame.Grid, gridFromNDC);
  p.SetMat4Array("voxelFromNDC", 1, gridFromNDC);
  vtkMatrix4x4* view = frame.Renderer->GetActiveCamera()->GetViewTransformMatrix();
  float normalToGrid[9];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      // inverse of the rotation = its transpose; GLSL matrices are column-major
      normalToGrid[c * 3 + r] = static_cast<float>(view->GetElement(c, r));
    }
  }
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

void ConeTrace::Run(const Frame& frame)
{
  ScopedStage stage(*frame.Clock, vtkVoxelGIPass::STAGE_CONE_TRACE);
  ComputeProgram& p = this->Program;
  p.Use(frame.Window);
  SamplerBindings samplers(frame.Window);
  SetConeTracingSamplers(
    p, samplers, this->Lighting.GetRadiance(), this->Mipmap, 0.0f, this->Cones.StepFactor);
  ScopedTextures inputs(
    { this->GBuffer.GetNormal(), this->GBuffer.GetMaterial(), this->GBuffer.GetDepth() });
  if (!(samplers.Complete() && inputs.Complete()))
  {
    return;
  }
  this->SetUniforms(frame);
  BindImage2D(0, this->Indirect, GL_WRITE_ONLY, GL_RGBA16F);
  BindImage2D(1, this->Shadowed, GL_WRITE_ONLY, GL_RGBA16F);
  p.DispatchImage(this->Indirect->GetWidth(), this->Indirect->GetHeight(), Tile);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void ConeTrace::ReleaseGraphicsResources(vtkWindow* window)
{
  for (vtkTextureObject* texture : { this->Indirect.Get(), this->Shadowed.Get() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(window);
    }
  }
  this->Indirect = this->Shadowed = nullptr;
  this->Program.Release();
}

}
