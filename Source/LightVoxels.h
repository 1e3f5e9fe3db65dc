/**
 * LightVoxels stage (light_voxels.comp): the radiance volume (RGBA16F, rgb outgoing radiance,
 * a occupancy). Every occupied voxel is lit directly by the lights of the light block, with
 * the normal-weighted attenuation of deferred voxel shading, occluded by soft voxel shadows
 * (a raymarch through the occupancy) or by shadow maps, plus its emission. With bounces the
 * direct light is also kept in a second volume, which VoxelBounce adds the indirect light to.
 */
#ifndef VoxelGILightVoxels_h
#define VoxelGILightVoxels_h

#include "GLHelpers.h"

#include <string>
#include <vector>

class vtkWindow;

namespace voxelgi
{
struct Frame;
struct Settings;
class ShadowMaps;
class VoxelizePass;

class LightVoxels
{
public:
  LightVoxels(const VoxelizePass& voxels, const ShadowMaps& shadows)
    : Voxels(voxels)
    , Shadows(shadows)
  {
  }

  /// Allocate the volumes for the frame's grid (a mip chain when mipmaps are isotropic, the
  /// direct volume when bouncing) and build the program for its occlusion mode.
  bool Prepare(const Frame& frame, std::string& error);
  /// The bytes Prepare allocates for a grid of `resolution` with `settings`.
  static std::size_t RequiredBytes(int resolution, const Settings& settings);
  /// Direct light and emission into the radiance (and direct) volume. When the plan
  /// continues the last solution (LightWork::Continue, with bounces), the indirect light of
  /// the last bounces (radiance minus direct, both as they were) is added to the new direct
  /// light, so that one bounce can continue from it.
  void Run(const Frame& frame);
  void ReleaseGraphicsResources(vtkWindow* window);

  Volume3D& GetRadiance() { return this->Radiance; }
  const Volume3D& GetRadiance() const { return this->Radiance; }
  const Volume3D& GetDirect() const { return this->Direct; }
  std::size_t MemoryBytes() const { return this->Radiance.Bytes() + this->Direct.Bytes(); }

private:
  const VoxelizePass& Voxels;
  const ShadowMaps& Shadows;
  Volume3D Radiance;
  Volume3D Direct; // kept only when bouncing
  GLProgram Program;
  bool WithShadowMaps = false; // the program's variant
  bool VoxelShadows = true;
};

}

#endif
