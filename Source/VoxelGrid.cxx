#include "VoxelGrid.h"

#include <algorithm>
#include <cmath>

namespace voxelgi
{

bool VoxelGrid::Covers(const double bounds[6]) const
{
  if (!this->IsValid())
  {
    return false;
  }
  const double size = this->Size();
  for (int a = 0; a < 3; ++a)
  {
    if (bounds[2 * a] < this->Origin[a] || bounds[2 * a + 1] > this->Origin[a] + size)
    {
      return false;
    }
  }
  return true;
}

FitStatus FitVoxelGrid(const double bounds[6], int resolution, double padding, VoxelGrid& grid)
{
  for (int i = 0; i < 6; ++i)
  {
    if (!std::isfinite(bounds[i]))
    {
      return FitStatus::NonFiniteBounds;
    }
  }
  if (bounds[0] > bounds[1] || bounds[2] > bounds[3] || bounds[4] > bounds[5])
  {
    return FitStatus::EmptyBounds;
  }
  const glm::dvec3 lo(bounds[0], bounds[2], bounds[4]);
  const glm::dvec3 hi(bounds[1], bounds[3], bounds[5]);
  const glm::dvec3 center = 0.5 * (lo + hi);
  double extent = std::max(hi.x - lo.x, std::max(hi.y - lo.y, hi.z - lo.z));
  // A zero-volume scene (one point) still needs voxels of some size: relative to the
  // coordinates' magnitude, so that 1e8-offset points do not get sub-ulp voxels, at least 1.
  const double magnitude = std::max(std::abs(center.x), std::max(std::abs(center.y), std::abs(center.z)));
  if (!(extent > magnitude * 1e-12))
  {
    extent = std::max(magnitude * 1e-6, 1.0);
  }
  const double size = extent * (1.0 + 2.0 * std::max(padding, 0.0));
  grid.Resolution = resolution;
  grid.VoxelSize = size / resolution;
  grid.Origin = center - glm::dvec3(0.5 * size);
  grid.SetScene(bounds);
  return FitStatus::Ok;
}

void VoxelGrid::SetScene(const double bounds[6])
{
  this->SceneLo = glm::dvec3(bounds[0], bounds[2], bounds[4]);
  this->SceneHi = glm::dvec3(bounds[1], bounds[3], bounds[5]);
}

void VoxelGrid::SceneVoxels(glm::dvec3& lo, glm::dvec3& hi) const
{
  const glm::dvec3 all(this->Resolution);
  lo = glm::dvec3(0.0);
  hi = all;
  if (!this->IsValid() || !(glm::all(glm::lessThanEqual(this->SceneLo, this->SceneHi))))
  {
    return;
  }
  // NaN-safe: a comparison that fails keeps the grid's face
  lo = glm::clamp(glm::floor(this->ToVoxel(this->SceneLo)), glm::dvec3(0.0), all);
  hi = glm::clamp(glm::ceil(this->ToVoxel(this->SceneHi)), lo, all);
}

int ClampResolution(int resolution, int minimum, int maximum)
{
  int best = minimum;
  for (int p = minimum; p <= maximum; p *= 2)
  {
    if (std::abs(p - resolution) < std::abs(best - resolution) ||
      (std::abs(p - resolution) == std::abs(best - resolution) && p > best))
    {
      best = p;
    }
  }
  return best;
}

}
