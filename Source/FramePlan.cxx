#include "FramePlan.h"

#include "Frame.h"

#include <cmath>

namespace voxelgi
{

namespace
{
// What the radiance, its mipmaps and bounces depend on beyond voxels and lights, and where
// its voxels are.
std::vector<double> RadianceKey(const Settings& c, const VoxelGrid& grid)
{
  return { static_cast<double>(c.LightOcclusion), static_cast<double>(c.ShadowMapResolution),
    static_cast<double>(c.Bounces), static_cast<double>(c.BounceTail),
    static_cast<double>(c.AnisotropicMipmaps),
    static_cast<double>(c.DiffuseConeCount), c.DiffuseConeAperture, c.ConeStepFactor,
    c.MaxTraceDistance * grid.Resolution, grid.Origin.x, grid.Origin.y, grid.Origin.z,
    grid.VoxelSize };
}
}

LightWork FrameHistory::PlanLights(bool voxelsChange, bool lightsChanged, double turn,
  const Settings& settings, const VoxelGrid& grid, bool interactive) const
{
  const bool sameGrid = this->LitValid && this->LitKey == RadianceKey(settings, grid);
  const bool current = !voxelsChange && sameGrid && this->LitVoxels == this->VoxelGeneration;
  // Camera-following lights turn with every camera move: their voxel light is kept until
  // they have turned by more than CameraLightTurn (VTK's own direct light stays exact).
  const bool turned = lightsChanged && !(turn <= settings.CameraLightTurn);
  if (current && !turned)
  {
    // The first still frame after interactive relights converges.
    return this->LitPartly && !interactive ? LightWork::Relight : LightWork::Current;
  }
  // Only camera lights turned, and the last solution is for these voxels and settings: the
  // relight continues from it, and the frame counts as a camera move for the trace.
  if (current && std::isfinite(turn))
  {
    return LightWork::Continue;
  }
  // While VTK renders interactively, the last solution on the same grid is the start of the
  // new one: one bounce on from it (a relight that bounces once would lose the rest).
  return interactive && sameGrid && settings.Bounces > 1 ? LightWork::Progress
                                                         : LightWork::Relight;
}

void FrameHistory::Lit(LightWork work, bool valid, const Settings& settings, const VoxelGrid& grid)
{
  this->LitValid = valid;
  this->LitPartly = valid && work == LightWork::Progress;
  this->LitVoxels = this->VoxelGeneration;
  this->LitKey = RadianceKey(settings, grid);
  this->Radiance.Generation += (work != LightWork::Continue || !valid) ? 1 : 0;
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
