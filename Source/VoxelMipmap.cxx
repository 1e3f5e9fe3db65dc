#include "VoxelMipmap.h"

#include "Frame.h"
#include "LightVoxels.h"
#include "VoxelizePass.h"
#include "VoxelGIShaders.h"
#include "shader_interface.h"
#include "StageIds.h"

#include "vtk_glew.h"

#include <algorithm>

namespace voxelgi
{

namespace
{
const char* const SourceNames[6] = { "voxelPosX", "voxelNegX", "voxelPosY", "voxelNegY",
  "voxelPosZ", "voxelNegZ" };
}

int MipLevels(int resolution)
{
  int levels = 1;
  while ((resolution >> levels) > 0)
  {
    ++levels;
  }
  return levels;
}

std::size_t VoxelMipmap::RequiredBytes(int resolution, const Settings& settings)
{
  const int half = std::max(resolution / 2, 1);
  // (with media, the RG8 medium volume adds a 24th of that)
  return settings.AnisotropicMipmaps ? 6 * Volume3D::StorageBytes(GL_RGBA16F, half, MipLevels(half))
                                     : 0;
}

bool VoxelMipmap::Prepare(const Frame& frame, std::string& error)
{
  const int resolution = frame.Grid.Resolution;
  const bool anisotropic = frame.Config.AnisotropicMipmaps;
  this->Anisotropic = anisotropic;
  if (!anisotropic)
  {
    for (auto& volume : this->Directional)
    {
      volume.Release();
    }
    this->Medium.Release();
    return true;
  }
  const int half = std::max(resolution / 2, 1);
  for (auto& volume : this->Directional)
  {
    if (!volume.Allocate(GL_RGBA16F, half, MipLevels(half)))
    {
      error = "could not allocate the directional (anisotropic) volumes";
      return false;
    }
  }
  if (!this->Voxels.HasMedia())
  {
    this->Medium.Release();
  }
  else if (!this->Medium.Allocate(GL_RG8, half, MipLevels(half)))
  {
    error = "could not allocate the directional volumes' medium shares";
    return false;
  }
  return this->Program.BuildOnce(shaders::voxel_mipmap_comp, "anisotropic mipmap", error);
}

void VoxelMipmap::Run(const Frame& frame)
{
  ScopedStage stage(*frame.Clock, stage::Mipmap);
  this->Build(frame.Window);
}

void VoxelMipmap::Build(vtkOpenGLRenderWindow* renWin)
{
  Volume3D& radiance = this->Lighting.GetRadiance();
  if (!this->Anisotropic)
  {
    radiance.GenerateMipmaps();
    return;
  }
  SamplerBindings samplers(renWin);
  const int radianceUnit = samplers.Add(radiance);
  const Volume3D& direct = this->Lighting.GetDirect();
  const int normalUnit = samplers.Add(this->Voxels.GetNormal());
  const int directUnit = samplers.Add(direct.IsAllocated() ? direct : radiance);
  int units[6];
  for (int d = 0; d < 6; ++d)
  {
    units[d] = samplers.Add(this->Directional[d]);
  }
  const bool media = this->Medium.IsAllocated();
  const int mediumUnit = samplers.Add(media ? this->Medium : this->Directional[0]);
  if (!samplers.Complete())
  {
    return;
  }
  this->Program.Use(renWin);
  this->Program.SetInt("voxelRadiance", radianceUnit);
  this->Program.SetInt("voxelNormal", normalUnit);
  this->Program.SetInt("voxelDirect", directUnit);
  this->Program.SetInt("litSides", direct.IsAllocated() ? 1 : 0);
  this->Program.SetInt("media", media ? 1 : 0);
  this->Program.SetInt("voxelMedium", mediumUnit);
  for (int d = 0; d < 6; ++d)
  {
    this->Program.SetInt(SourceNames[d], units[d]);
  }
  const int levels = this->Directional[0].Levels();
  for (int level = 0; level < levels; ++level)
  {
    const int size = std::max(this->Directional[0].Resolution() >> level, 1);
    for (int d = 0; d < 6; ++d)
    {
      this->Directional[d].BindImage(static_cast<unsigned int>(d), GL_WRITE_ONLY, level);
    }
    if (media)
    {
      this->Medium.BindImage(6, GL_WRITE_ONLY, level);
    }
    this->Program.Use(renWin);
    this->Program.SetInt("sourceIsRadiance", level == 0 ? 1 : 0);
    this->Program.SetInt("sourceLevel", level - 1);
    this->Program.SetInt("targetSize", size);
    this->Program.DispatchCube(size, VOXELGI_LOCAL_SIZE);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
}

std::size_t VoxelMipmap::MemoryBytes() const
{
  std::size_t bytes = 0;
  for (const auto& volume : this->Directional)
  {
    bytes += volume.Bytes();
  }
  return bytes + this->Medium.Bytes();
}

void VoxelMipmap::ReleaseGraphicsResources(vtkWindow*)
{
  for (auto& volume : this->Directional)
  {
    volume.Release();
  }
  this->Medium.Release();
  this->Program.Release();
}

}
