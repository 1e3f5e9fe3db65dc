#include "ConeSettings.h"

#include "Frame.h"

#include "vtkMath.h"

#include <algorithm>
#include <cmath>

namespace voxelgi
{

void ConeSettings::Set(int count, double apertureDegrees, double stepFactor, double maxDistance)
{
  this->Count = std::max(1, std::min(count, VOXELGI_MAX_CONES));
  const double halfAngle = vtkMath::RadiansFromDegrees(0.5 * apertureDegrees);
  const double golden = vtkMath::Pi() * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < this->Count; ++i)
  {
    // Cosine-weighted stratified spiral: cone i sits at the centre of the i-th of Count
    // strata of equal cosine-weighted solid angle (sin^2 of the polar angle uniform), so
    // that equal-weight cones estimate irradiance / pi. The polar angles are not compressed
    // toward the normal (that over-weighted light from above and missed light near the
    // horizon); the cone tracer keeps a cone off its own surface's voxels by the level it
    // samples near the surface (Shaders/cone_tracing.glsl).
    const double u = this->Count == 1 ? 0.0 : (i + 0.5) / this->Count;
    const double polar = std::asin(std::sqrt(u));
    const double phi = golden * i;
    this->Directions[3 * i] = static_cast<float>(std::sin(polar) * std::cos(phi));
    this->Directions[3 * i + 1] = static_cast<float>(std::sin(polar) * std::sin(phi));
    this->Directions[3 * i + 2] = static_cast<float>(std::cos(polar));
  }
  this->TanHalf = static_cast<float>(std::tan(halfAngle));
  this->StepFactor = static_cast<float>(stepFactor);
  this->MaxDistance = static_cast<float>(maxDistance);
}

void ConeSettings::Set(const Settings& settings, int resolution)
{
  this->Set(settings.DiffuseConeCount, settings.DiffuseConeAperture, settings.ConeStepFactor,
    settings.MaxTraceDistance * resolution);
}

const char* const ConeTracingInputs::SamplerNames[7] = { "voxelRadiance", "voxelPosX",
  "voxelNegX", "voxelPosY", "voxelNegY", "voxelPosZ", "voxelNegZ" };

ConeTracingInputs BindConeTracing(SamplerBindings& samplers, const Volume3D& radiance,
  const VoxelMipmap& mips, float minLevel, float stepFactor)
{
  ConeTracingInputs inputs;
  inputs.Units[0] = samplers.Add(radiance);
  for (int d = 0; d < 6; ++d)
  {
    // Isotropic mode has no directional volumes: point the samplers at the radiance volume.
    inputs.Units[1 + d] = samplers.Add(mips.IsAnisotropic() ? mips.Directional[d] : radiance);
  }
  inputs.Isotropic = mips.IsAnisotropic() ? 0 : 1;
  inputs.MinLevel = minLevel;
  inputs.StepFactor = stepFactor;
  return inputs;
}

void SetConeTracingSamplers(GLProgram& program, SamplerBindings& samplers,
  const Volume3D& radiance, const VoxelMipmap& mips, float minLevel, float stepFactor)
{
  const ConeTracingInputs inputs = BindConeTracing(samplers, radiance, mips, minLevel, stepFactor);
  for (int i = 0; i < 7; ++i)
  {
    program.SetInt(ConeTracingInputs::SamplerNames[i], inputs.Units[i]);
  }
  program.SetInt("voxelIsotropic", inputs.Isotropic);
  program.SetFloat("voxelMinLevel", inputs.MinLevel);
  program.SetFloat("coneStepFactor", inputs.StepFactor);
}

}
