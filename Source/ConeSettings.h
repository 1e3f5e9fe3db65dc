/**
 * Host side of Shaders/cone_tracing.glsl, the voxel cone tracing shared by the per-voxel
 * VoxelBounce and the per-pixel ConeTrace: the cone directions and the samplers and uniforms
 * of the radiance volume and its mipmaps.
 */
#ifndef VoxelGIConeSettings_h
#define VoxelGIConeSettings_h

#include "GLHelpers.h"
#include "VoxelMipmap.h"
#include "shader_interface.h"

namespace voxelgi
{
struct Settings;

/// Cone parameters shared by the bounce and the per-pixel trace.
struct ConeSettings
{
  float Directions[VOXELGI_MAX_CONES * 3]; // tangent space, z along the normal
  int Count = 0;
  float TanHalf = 0.f;
  float StepFactor = 1.f;
  float MaxDistance = 0.f; // voxels

  /// Fill `count` cosine-distributed directions (a golden-angle spiral over the whole
  /// hemisphere, one per stratum of equal cosine-weighted solid angle, so that equal weights
  /// estimate irradiance / pi) for cones of full aperture `apertureDegrees`.
  void Set(int count, double apertureDegrees, double stepFactor, double maxDistance);
  /// The same from the settings of a grid of `resolution` voxels.
  void Set(const Settings& settings, int resolution);
};

/// The cone-tracing samplers (Shaders/cone_tracing.glsl) bound to texture units, and their
/// uniforms, for a program of any kind.
struct ConeTracingInputs
{
  static const char* const SamplerNames[7];
  int Units[7] = { -1, -1, -1, -1, -1, -1, -1 };
  int Isotropic = 1;
  float MinLevel = 0.f;
  float StepFactor = 1.f;
};

/// Bind the radiance volume and its mipmaps to units of `samplers`, reading mip levels from
/// `minLevel` on.
ConeTracingInputs BindConeTracing(SamplerBindings& samplers, const Volume3D& radiance,
  const VoxelMipmap& mips, float minLevel, float stepFactor);

/// Bind the cone-tracing samplers and uniforms (Shaders/cone_tracing.glsl) of `program`,
/// reading mip levels from `minLevel` on.
void SetConeTracingSamplers(GLProgram& program, SamplerBindings& samplers,
  const Volume3D& radiance, const VoxelMipmap& mips, float minLevel, float stepFactor);

}

#endif
