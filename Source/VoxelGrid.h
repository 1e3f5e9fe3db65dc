/**
 * The voxel grid: a cube of `Resolution`^3 cubic voxels fitted around the scene bounds.
 * Pure CPU math (GLM, double precision) so it can be unit tested without a GL context.
 * The origin is kept in double: shaders only ever see coordinates relative to it, which is
 * what keeps scenes far from the world origin (1e8) precise.
 */
#ifndef VoxelGIVoxelGrid_h
#define VoxelGIVoxelGrid_h

#include <glm/glm.hpp>

namespace voxelgi
{

struct VoxelGrid
{
  glm::dvec3 Origin{ 0.0 }; // world position of the grid's minimum corner
  double VoxelSize = 0.0;   // edge length of one voxel, world units
  int Resolution = 0;       // voxels per axis
  /// The bounds of the scene the voxels hold (world; empty, lo > hi: unknown). Nothing lies
  /// outside them, so cones end at their faces (cone_tracing.glsl) and not in the grid's
  /// empty margins: a room lower than it is wide has its floor and ceiling deep inside the
  /// cubic grid.
  glm::dvec3 SceneLo{ 1.0 };
  glm::dvec3 SceneHi{ 0.0 };

  bool IsValid() const { return this->Resolution > 0 && this->VoxelSize > 0.0; }
  double Size() const { return this->VoxelSize * this->Resolution; }
  glm::dvec3 Center() const { return this->Origin + glm::dvec3(0.5 * this->Size()); }
  /// World position -> continuous voxel coordinates (voxel i spans [i, i+1)).
  glm::dvec3 ToVoxel(const glm::dvec3& world) const
  {
    return (world - this->Origin) / this->VoxelSize;
  }
  /// True when the bounds (xmin,xmax,ymin,ymax,zmin,zmax) lie inside the grid.
  bool Covers(const double bounds[6]) const;
  /// Keep `bounds` (xmin,xmax,...) as the scene's (SceneLo, SceneHi).
  void SetScene(const double bounds[6]);
  /// The scene's bounds in voxel coordinates, whole voxels, within [0, Resolution]; the
  /// whole grid when they are unknown.
  void SceneVoxels(glm::dvec3& lo, glm::dvec3& hi) const;
};

/// Why a grid could not be fitted.
enum class FitStatus
{
  Ok,
  EmptyBounds,    // uninitialized bounds (min > max): nothing to voxelize
  NonFiniteBounds // NaN or Inf in the bounds
};

/**
 * Fit a grid around `bounds`: cubic voxels, the largest extent plus `padding` (a fraction of
 * that extent) on each side, centred on the bounds, which it keeps as the scene's. Flat or
 * zero-volume bounds still give a valid grid: a zero extent falls back to a size relative to
 * the coordinates' magnitude.
 */
FitStatus FitVoxelGrid(const double bounds[6], int resolution, double padding, VoxelGrid& grid);

/// Round to the nearest power of two within [minimum, maximum] (both powers of two).
int ClampResolution(int resolution, int minimum, int maximum);

}

#endif
