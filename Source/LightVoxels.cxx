#include "LightVoxels.h"

#include "Frame.h"
#include "ShadowMaps.h"
#include "VoxelGIShaders.h"
#include "VoxelMipmap.h"
#include "VoxelizePass.h"
#include "StageIds.h"

#include "vtk_glew.h"

namespace voxelgi
{

namespace
{
/// Isotropic mipmaps live in the radiance volume's own mip chain.
int RadianceLevels(int resolution, const Settings& settings)
{
  return settings.AnisotropicMipmaps ? 1 : MipLevels(resolution);
}
}

std::size_t LightVoxels::RequiredBytes(int resolution, const Settings& settings)
{
  return Volume3D::StorageBytes(
           GL_RGBA16F, resolution, RadianceLevels(resolution, settings)) +
    (settings.Bounces > 0 ? Volume3D::StorageBytes(GL_RGBA16F, resolution) : 0);
}

bool LightVoxels::Prepare(const Frame& frame, std::string& error)
{
  const Settings& config = frame.Config;
  const int resolution = frame.Grid.Resolution;
  bool ok =
    this->Radiance.Allocate(GL_RGBA16F, resolution, RadianceLevels(resolution, config));
  if (config.Bounces > 0)
  {
    ok = ok && this->Direct.Allocate(GL_RGBA16F, resolution);
  }
  else
  {
    this->Direct.Release();
  }
  if (!ok)
  {
    error = "could not allocate the radiance volume";
    return false;
  }
  this->VoxelShadows = config.LightOcclusion != LIGHT_OCCLUSION_NONE;
  // The shadow-map variant is compiled only when a scene uses it.
  this->WithShadowMaps = this->Shadows.HasMaps();
  return this->Program.BuildOnce(shaders::light_voxels_comp, "voxel lighting", error,
    this->WithShadowMaps ? "#define VOXELGI_SHADOW_MAPS\n" : "");
}

void LightVoxels::Run(const Frame& frame)
{
  ScopedStage stage(*frame.Clock, stage::LightVoxels);
  const VoxelizePass& voxels = this->Voxels;
  SamplerBindings samplers(frame.Window);
  const int albedo = samplers.Add(voxels.GetAlbedo());
  const int normal = samplers.Add(voxels.GetNormal());
  const int emission =
    samplers.Add(voxels.HasEmission() ? voxels.GetEmission() : voxels.GetAlbedo());
  GLProgram& p = this->Program;
  p.Use(frame.Window);
  p.SetInt("voxelAlbedo", albedo);
  p.SetInt("voxelNormal", normal);
  p.SetInt("voxelEmission", emission);
  p.SetInt("hasEmission", voxels.HasEmission() ? 1 : 0);
  p.SetInt("voxelShadows", this->VoxelShadows ? 1 : 0);
  if (this->WithShadowMaps)
  {
    this->Shadows.Bind(p, samplers);
  }
  if (!(samplers.Complete()))
  {
    return;
  }
  const bool direct = this->Direct.IsAllocated();
  const bool keep =
    (frame.Plan.Lights == LightWork::Continue || frame.Plan.Lights == LightWork::Progress) &&
    direct;
  p.SetInt("writeDirect", direct ? 1 : 0);
  p.SetInt("keepIndirect", keep ? 1 : 0);
  const GLenum access = keep ? GL_READ_WRITE : GL_WRITE_ONLY;
  this->Radiance.BindImage(0, access);
  // Without a direct volume the second image unit still needs a matching format behind it.
  (direct ? this->Direct : this->Radiance).BindImage(1, access);
  // The whole grid: empty voxels get zero (a clear of the volumes first, glClearTexImage,
  // cost twenty times this dispatch on the H200), and the bounce then writes only the
  // occupied bricks.
  p.DispatchCube(this->Radiance.Resolution(), VOXELGI_LOCAL_SIZE);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void LightVoxels::ReleaseGraphicsResources(vtkWindow*)
{
  this->Radiance.Release();
  this->Direct.Release();
  this->Program.Release();
}

}
