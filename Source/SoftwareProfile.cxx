#include "SoftwareProfile.h"

#include <algorithm>
#include <cctype>

namespace voxelgi
{

bool IsSoftwareRenderer(const std::string& renderer)
{
  std::string name(renderer);
  std::transform(name.begin(), name.end(), name.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* software : { "llvmpipe", "softpipe", "swr (", "swiftshader",
         "software rasterizer", "gdi generic", "basic render driver" })
  {
    if (name.find(software) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

bool SoftwareProfileApplies(int profile, bool software)
{
  return profile == SOFTWARE_PROFILE_ON || (profile == SOFTWARE_PROFILE_AUTO && software);
}

void ApplySoftwareProfile(Settings& settings)
{
  // Measured on Mesa llvmpipe (2 cores, docs/performance.md): the voxel stages at 128^3 take
  // most of a first image, the trace scales with its pixels and cones. Bounces stay: the
  // emissive box keeps half its light through them (FLIP 0.34 with four, 0.51 with one).
  settings.VoxelResolution = std::min(settings.VoxelResolution, 64);
  settings.DiffuseConeCount = std::min(settings.DiffuseConeCount, 4);
  settings.TraceResolution = std::min(settings.TraceResolution, 0.25);
  settings.ShadowMapResolution = std::min(settings.ShadowMapResolution, 256);
}

}
