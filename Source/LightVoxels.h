/**
 * LightVoxels and Bounce stages: the radiance volume (RGBA16F, rgb outgoing radiance, a
 * occupancy). Inject lights every voxel directly from the lights (with soft voxel shadows)
 * and adds its emission; each bounce then adds albedo x the indirect diffuse light gathered by
 * cones from the previous radiance's mipmaps.
 */
#ifndef VoxelGIVoxelLighting_h
#define VoxelGIVoxelLighting_h

#include "GLHelpers.h"

#include <string>

class vtkOpenGLRenderWindow;

namespace voxelgi
{
class ShadowMaps;
class Voxelizer;
class VoxelMipmap;

/// Cone parameters shared by the bounce and the per-pixel trace.
struct ConeSettings
{
  float Directions[16 * 3]; // tangent space, z along the normal
  int Count = 0;
  float TanHalf = 0.f;
  float StepFactor = 1.f;
  float MaxDistance = 0.f; // voxels

  /// Fill `count` cosine-distributed directions (a golden-angle spiral over the hemisphere,
  /// kept clear of the surface's own plane) for cones of full aperture `apertureDegrees`.
  void Set(int count, double apertureDegrees, double stepFactor, double maxDistance);
};

/// Bind the cone-tracing samplers and uniforms (Shaders/cone_tracing.glsl) of `program`
/// through `set`, a callable (name, int|float) -> void.
template <typename Setter>
void SetConeTracingSamplers(SamplerBindings& samplers, const Volume3D& radiance,
  const VoxelMipmap& mips, float minLevel, float stepFactor, Setter&& set);

class VoxelLighting
{
public:
  bool Prepare(int resolution, bool mipmapped, bool keepDirect, std::string& error);
  /// Direct light and emission into the radiance volume. `shadowMaps` (may be null) occlude
  /// the lights that have one; `voxelShadows` raymarches for the others.
  bool Inject(vtkOpenGLRenderWindow* renWin, const Voxelizer& voxels, bool voxelShadows,
    const ShadowMaps* shadowMaps, std::string& error);
  /// One bounce of indirect diffuse light (needs the mipmaps of the current radiance).
  void Bounce(vtkOpenGLRenderWindow* renWin, const Voxelizer& voxels, const VoxelMipmap& mips,
    const ConeSettings& cones);

  Volume3D Radiance;
  Volume3D Direct; // kept only when bouncing
  std::size_t MemoryBytes() const { return this->Radiance.Bytes() + this->Direct.Bytes(); }
  void ReleaseGraphicsResources();

private:
  ComputeProgram InjectProgram;
  bool InjectWithShadowMaps = false;
  ComputeProgram BounceProgram;
};

}

#include "VoxelMipmap.h"

namespace voxelgi
{
template <typename Setter>
void SetConeTracingSamplers(SamplerBindings& samplers, const Volume3D& radiance,
  const VoxelMipmap& mips, float minLevel, float stepFactor, Setter&& set)
{
  static const char* const names[6] = { "voxelPosX", "voxelNegX", "voxelPosY", "voxelNegY",
    "voxelPosZ", "voxelNegZ" };
  set("voxelRadiance", samplers.Add(radiance));
  for (int d = 0; d < 6; ++d)
  {
    // Isotropic mode has no directional volumes: point the samplers at the radiance volume.
    set(names[d], samplers.Add(mips.IsAnisotropic() ? mips.Directional[d] : radiance));
  }
  set("voxelIsotropic", mips.IsAnisotropic() ? 0 : 1);
  set("voxelMinLevel", minLevel);
  set("coneStepFactor", stepFactor);
}
}

#endif
