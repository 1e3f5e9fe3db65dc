/**
 * The voxel memory rule: what the voxel volumes of a configuration need, per stage, and
 * whether that fits the memory the GL reports free. Checked before the volumes are made; a
 * need found to fit is not asked again until it changes.
 */
#ifndef VoxelGIVoxelMemory_h
#define VoxelGIVoxelMemory_h

#include <cstddef>
#include <string>
#include <vector>

class vtkLight;

namespace voxelgi
{
struct Settings;

/// What the voxel volumes of `settings` need, per stage (with the channels of emission and of
/// translucent surfaces where the scene has them), and the shadow maps of `lights`.
struct VoxelMemoryNeed
{
  std::size_t Voxelization, Radiance, Mipmaps, ShadowMaps;
  VoxelMemoryNeed(bool emission, bool translucent, const Settings& settings,
    const std::vector<vtkLight*>& lights = {});
  /// The volumes, refused when they do not fit (the shadow maps degrade instead).
  std::size_t Volumes() const { return this->Voxelization + this->Radiance + this->Mipmaps; }
  std::size_t Total() const { return this->Volumes() + this->ShadowMaps; }
};

class VoxelMemory
{
public:
  /// Whether the volumes of `settings` (with `emission`, `translucent`) fit the free memory,
  /// counting the `held` bytes the pass frees before making them; if not, `error` says why.
  bool Fits(bool emission, bool translucent, const Settings& settings, std::size_t held,
    std::string& error);
  /// The volumes were freed: check again before the next ones.
  void Forget() { this->FittingBytes = 0; }

private:
  std::size_t FittingBytes = 0; // the last need found to fit
};

}

#endif
