#include "VoxelLighting.h"

#include "VoxelGIShaders.h"
#include "ShadowMaps.h"
#include "VoxelLights.h"
#include "Voxelizer.h"

#include "vtkMath.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace voxelgi
{

namespace
{
constexpr int LocalSize = 4;
}

void ConeSettings::Set(int count, double apertureDegrees, double stepFactor, double maxDistance)
{
  this->Count = std::max(1, std::min(count, 16));
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

bool VoxelLighting::Prepare(int resolution, bool mipmapped, bool keepDirect, std::string& error)
{
  const int levels = mipmapped ? MipLevels(resolution) : 1;
  bool ok = this->Radiance.Allocate(GL_RGBA16F, resolution, levels);
  if (keepDirect)
  {
    ok = ok && this->Direct.Allocate(GL_RGBA16F, resolution);
  }
  else
  {
    this->Direct.Release();
  }
  if (!ok)
  {
    error = "could not allocate the radiance volume";
    return false;
  }
  std::string log;
  if (!this->BounceProgram.IsReady() &&
    !this->BounceProgram.Build("", shaders::inject_propagation_comp, log))
  {
    error = "voxel bounce shader failed to build: " + log;
    return false;
  }
  return true;
}

bool VoxelLighting::Inject(vtkOpenGLRenderWindow* renWin, const Voxelizer& voxels,
  bool voxelShadows, const ShadowMaps* shadowMaps, std::string& error)
{
  // The shadow-map variant is compiled only when a scene uses it.
  const bool withMaps = shadowMaps && shadowMaps->Maps.Layers() > 0;
  if (!this->InjectProgram.IsReady() || withMaps != this->InjectWithShadowMaps)
  {
    std::string log;
    if (!this->InjectProgram.Build(withMaps ? "#define VOXELGI_SHADOW_MAPS\n" : "",
          shaders::inject_radiance_comp, log))
    {
      error = "voxel lighting shader failed to build: " + log;
      return false;
    }
    this->InjectWithShadowMaps = withMaps;
  }
  SamplerBindings samplers(renWin);
  const int albedo = samplers.Add(voxels.AlbedoVolume);
  const int normal = samplers.Add(voxels.NormalVolume);
  const int emission = samplers.Add(voxels.HasEmission() ? voxels.EmissionVolume : voxels.AlbedoVolume);
  ComputeProgram& p = this->InjectProgram;
  p.Use(renWin);
  p.BindUniformBlock("VoxelLightBlock", VoxelLights::Binding);
  p.SetInt("voxelAlbedo", albedo);
  p.SetInt("voxelNormal", normal);
  p.SetInt("voxelEmission", emission);
  p.SetInt("hasEmission", voxels.HasEmission() ? 1 : 0);
  p.SetInt("voxelShadows", voxelShadows ? 1 : 0);
  if (withMaps)
  {
    p.SetInt("shadowMaps", samplers.Add(shadowMaps->Maps));
    p.SetIntArray("shadowLayers", ShadowMaps::MaxLights, shadowMaps->GetLayers());
    p.SetMat4Array("shadowMatrices", ShadowMaps::MaxLights, shadowMaps->GetMatrices());
  }
  const bool direct = this->Direct.IsAllocated();
  p.SetInt("writeDirect", direct ? 1 : 0);
  this->Radiance.BindImage(0, GL_WRITE_ONLY);
  // Without a direct volume the second image unit still needs a matching format behind it.
  (direct ? this->Direct : this->Radiance).BindImage(1, GL_WRITE_ONLY);
  p.DispatchCube(this->Radiance.Resolution(), LocalSize);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  return true;
}

void VoxelLighting::Bounce(vtkOpenGLRenderWindow* renWin, const Voxelizer& voxels,
  const VoxelMipmap& mips, const ConeSettings& cones)
{
  SamplerBindings samplers(renWin);
  ComputeProgram& p = this->BounceProgram;
  p.Use(renWin);
  p.BindUniformBlock("VoxelLightBlock", VoxelLights::Binding);
  // The bounce writes the radiance volume, so it reads only the mipmaps (level >= 1).
  SetConeTracingSamplers(samplers, this->Radiance, mips, 1.0f, cones.StepFactor,
    [&p](const char* name, auto value) {
      if constexpr (std::is_same_v<decltype(value), int>)
      {
        p.SetInt(name, value);
      }
      else
      {
        p.SetFloat(name, value);
      }
    });
  p.SetInt("voxelAlbedo", samplers.Add(voxels.AlbedoVolume));
  p.SetInt("voxelNormal", samplers.Add(voxels.NormalVolume));
  p.SetInt("voxelDirect", samplers.Add(this->Direct));
  p.SetVec3Array("coneDirections", cones.Count, cones.Directions);
  p.SetInt("coneCount", cones.Count);
  p.SetFloat("coneTanHalf", cones.TanHalf);
  p.SetFloat("maxDistance", cones.MaxDistance);
  this->Radiance.BindImage(0, GL_WRITE_ONLY);
  p.DispatchCube(this->Radiance.Resolution(), LocalSize);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void VoxelLighting::ReleaseGraphicsResources()
{
  this->Radiance.Release();
  this->Direct.Release();
  this->InjectProgram.Release();
  this->BounceProgram.Release();
}

}
