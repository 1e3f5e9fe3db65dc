#include "VoxelMemory.h"

#include "Frame.h"
#include "GLHelpers.h"
#include "LightVoxels.h"
#include "VoxelMipmap.h"
#include "VoxelizePass.h"

#include <sstream>

namespace voxelgi
{

VoxelMemoryNeed::VoxelMemoryNeed(bool emission, const Settings& settings)
  : Voxelization(VoxelizePass::RequiredBytes(settings.VoxelResolution, emission))
  , Radiance(LightVoxels::RequiredBytes(settings.VoxelResolution, settings))
  , Mipmaps(VoxelMipmap::RequiredBytes(settings.VoxelResolution, settings))
{
}

bool VoxelMemory::Fits(
  bool emission, const Settings& settings, std::size_t held, std::string& error)
{
  const VoxelMemoryNeed need(emission, settings);
  if (need.Total() == this->FittingBytes)
  {
    return true;
  }
  std::string source;
  const long long available = AvailableMemory(source);
  if (available >= 0 && need.Total() > static_cast<unsigned long long>(available) + held)
  {
    const auto mib = [](unsigned long long bytes) { return bytes / (1024 * 1024); };
    std::ostringstream msg;
    msg << "VoxelResolution " << settings.VoxelResolution << " needs " << mib(need.Total())
        << " MiB for its voxel volumes (voxelization " << mib(need.Voxelization)
        << ", radiance " << mib(need.Radiance) << ", mipmaps " << mib(need.Mipmaps)
        << " MiB) but only " << mib(available + held) << " MiB are free (" << source
        << "; a lower VoxelResolution needs an eighth per halving)";
    error = msg.str();
    return false;
  }
  this->FittingBytes = need.Total();
  return true;
}

}
