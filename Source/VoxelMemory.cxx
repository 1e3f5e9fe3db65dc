#include "VoxelMemory.h"

#include "Frame.h"
#include "GLHelpers.h"
#include "LightVoxels.h"
#include "ShadowMaps.h"
#include "VoxelMipmap.h"
#include "VoxelizePass.h"

#include <sstream>

namespace voxelgi
{

VoxelMemoryNeed::VoxelMemoryNeed(bool emission, bool translucent, const Settings& settings,
  const std::vector<vtkLight*>& lights)
  : Voxelization(VoxelizePass::RequiredBytes(settings.VoxelResolution, emission, translucent))
  , Radiance(LightVoxels::RequiredBytes(settings.VoxelResolution, settings))
  , Mipmaps(VoxelMipmap::RequiredBytes(settings.VoxelResolution, settings))
  , ShadowMaps(settings.LightOcclusion == LIGHT_OCCLUSION_SHADOW_MAPS
        ? ShadowMaps::RequiredBytes(settings.ShadowMapResolution, lights)
        : 0)
{
}

bool VoxelMemory::Fits(bool emission, bool translucent, const Settings& settings,
  std::size_t held, std::string& error)
{
  const VoxelMemoryNeed need(emission, translucent, settings);
  if (need.Volumes() == this->FittingBytes)
  {
    return true;
  }
  std::string source;
  const long long available = AvailableMemory(source);
  if (available >= 0 && need.Volumes() > static_cast<unsigned long long>(available) + held)
  {
    const auto mib = [](unsigned long long bytes) { return bytes / (1024 * 1024); };
    std::ostringstream msg;
    msg << "VoxelResolution " << settings.VoxelResolution << " needs " << mib(need.Volumes())
        << " MiB for its voxel volumes (voxelization " << mib(need.Voxelization)
        << ", radiance " << mib(need.Radiance) << ", mipmaps " << mib(need.Mipmaps)
        << " MiB) but only " << mib(available + held) << " MiB are free (" << source
        << "; a lower VoxelResolution needs an eighth per halving)";
    error = msg.str();
    return false;
  }
  this->FittingBytes = need.Volumes();
  return true;
}

}
