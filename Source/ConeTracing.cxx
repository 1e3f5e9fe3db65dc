#include "ConeTracing.h"

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
  // A cone tilted further than this from the normal would sweep through the voxels of the
  // surface it starts on (its lower edge sinks faster than its axis rises).
  const double maxPolar = 0.5 * vtkMath::Pi() - std::asin(std::min(std::tan(halfAngle), 1.0));
  const double golden = vtkMath::Pi() * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < this->Count; ++i)
  {
    // Cosine-weighted spiral (equal-weight cones then estimate irradiance / pi), its polar
    // angles compressed into [0, maxPolar].
    const double u = this->Count == 1 ? 0.0 : (i + 0.5) / this->Count;
    const double polar = std::asin(std::sqrt(u)) * maxPolar / (0.5 * vtkMath::Pi());
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

void SetConeTracingSamplers(ComputeProgram& program, SamplerBindings& samplers,
  const Volume3D& radiance, const VoxelMipmap& mips, float minLevel, float stepFactor)
{
  static const char* const names[6] = { "voxelPosX", "voxelNegX", "voxelPosY", "voxelNegY",
    "voxelPosZ", "voxelNegZ" };
  program.SetInt("voxelRadiance", samplers.Add(radiance));
  for (int d = 0; d < 6; ++d)
  {
    // Isotropic mode has no directional volumes: point the samplers at the radiance volume.
    program.SetInt(names[d], samplers.Add(mips.IsAnisotropic() ? mips.Directional[d] : radiance));
  }
  program.SetInt("voxelIsotropic", mips.IsAnisotropic() ? 0 : 1);
  program.SetFloat("voxelMinLevel", minLevel);
  program.SetFloat("coneStepFactor", stepFactor);
}

}
