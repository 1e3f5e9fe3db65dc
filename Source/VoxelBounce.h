/**
 * Bounce stage (voxel_bounce.comp): each bounce cone-traces every occupied voxel through the
 * mipmaps of the current radiance and sets radiance = direct + albedo x gathered, then the
 * mipmaps are rebuilt. Cone weights sum to one and albedo is below one, so repeated bounces
 * converge from below (energy bounded). With BounceTail the bounces sum the grid's increments
 * and the last adds the series' rest, extrapolated from the ratio of the last two.
 */
#ifndef VoxelGIVoxelBounce_h
#define VoxelGIVoxelBounce_h

#include "ConeSettings.h"
#include "GLHelpers.h"

#include <string>

class vtkWindow;

namespace voxelgi
{
struct Frame;
class LightVoxels;
class VoxelMipmap;
class VoxelizePass;

class VoxelBounce
{
public:
  VoxelBounce(const VoxelizePass& voxels, LightVoxels& lighting, VoxelMipmap& mipmap)
    : Voxels(voxels)
    , Lighting(lighting)
    , Mipmap(mipmap)
  {
  }

  bool Prepare(const Frame& frame, std::string& error);
  /// The plan's bounces, each followed by a rebuild of the mipmaps.
  void Run(const Frame& frame);
  /// The indirect light arriving at the volumes' voxels (the last bounce's), for VTK's volume
  /// shading (VolumeLighting); null in scenes without volumes.
  const Volume3D* GetIncident() const
  {
    return this->Incident.IsAllocated() ? &this->Incident : nullptr;
  }
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  /// Bounce `index` (1, 2, ...) of the relight; `last`: add the tail.
  void Bounce(const Frame& frame, int index, bool last);

  const VoxelizePass& Voxels;
  LightVoxels& Lighting;
  VoxelMipmap& Mipmap;
  ConeSettings Cones;
  GLProgram Program;
  Volume3D Incident;
  StorageBuffer Sums; // the increments per bounce and channel, and the last ratio (BounceTail)
};

}

#endif
