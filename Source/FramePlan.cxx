#include "FramePlan.h"

#include "Frame.h"

#include <cmath>

namespace voxelgi
{

namespace
{
// What the radiance, its mipmaps and bounces depend on beyond voxels and lights.
std::vector<double> RadianceKey(const Settings& c, int resolution)
{
  return { static_cast<double>(c.LightOcclusion), static_cast<double>(c.ShadowMapResolution),
    static_cast<double>(c.Bounces), static_cast<double>(c.AnisotropicMipmaps),
    static_cast<double>(c.DiffuseConeCount), c.DiffuseConeAperture, c.ConeStepFactor,
    c.MaxTraceDistance * resolution };
}
}

LightWork FrameHistory::PlanLights(bool voxelsChange, bool lightsChanged, double turn,
  const Settings& settings, int resolution) const
{
  const bool current = !voxelsChange && this->LitValid && this->LitVoxels == this->VoxelGeneration &&
    this->LitKey == RadianceKey(settings, resolution);
  // Camera-following lights turn with every camera move: their voxel light is kept until
  // they have turned by more than CameraLightTurn (VTK's own direct light stays exact).
  const bool turned = lightsChanged && !(turn <= settings.CameraLightTurn);
  if (current && !turned)
  {
    return LightWork::Current;
  }
  // Only camera lights turned, and the last solution is for these voxels and settings: the
  // relight continues from it, and the frame counts as a camera move for the trace.
  return current && std::isfinite(turn) ? LightWork::Continue : LightWork::Relight;
}

void FrameHistory::Lit(LightWork work, bool valid, const Settings& settings, int resolution)
{
  this->LitValid = valid;
  this->LitVoxels = this->VoxelGeneration;
  this->LitKey = RadianceKey(settings, resolution);
  this->Radiance.Generation += (work == LightWork::Relight || !valid) ? 1 : 0;
}

TraceWork FrameHistory::PlanTrace(const RadianceState& radiance, bool lightsReset,
  vtkMTimeType settingsTime, const std::vector<unsigned long long>& imageKey) const
{
  if (!this->HasImage || lightsReset || this->ImageRadiance != radiance.Generation ||
    this->ImageSettings != settingsTime)
  {
    return TraceWork::Full;
  }
  return imageKey == this->ImageKey ? TraceWork::Present : TraceWork::CameraOnly;
}

void FrameHistory::Traced(
  const RadianceState& radiance, vtkMTimeType settingsTime, std::vector<unsigned long long> imageKey)
{
  this->HasImage = true;
  this->ImageRadiance = radiance.Generation;
  this->ImageSettings = settingsTime;
  this->ImageKey = std::move(imageKey);
}

void FrameHistory::Forget()
{
  this->LitValid = false;
  this->HasImage = false;
  ++this->Radiance.Generation;
}

}
