// Grid fitting: cubic voxels around the bounds, padding, and the degenerate cases.
#include "VoxelGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using voxelgi::FitStatus;
using voxelgi::FitVoxelGrid;
using voxelgi::VoxelGrid;

TEST(VoxelGrid, FitsCubeAroundBoxWithPadding)
{
  const double bounds[6] = { 0, 10, -2, 2, 1, 3 };
  VoxelGrid grid;
  ASSERT_EQ(FitVoxelGrid(bounds, 64, 0.05, grid), FitStatus::Ok);
  EXPECT_EQ(grid.Resolution, 64);
  // largest extent 10, plus 5% on each side
  EXPECT_DOUBLE_EQ(grid.Size(), 11.0);
  EXPECT_DOUBLE_EQ(grid.VoxelSize, 11.0 / 64);
  EXPECT_DOUBLE_EQ(grid.Center().x, 5.0);
  EXPECT_DOUBLE_EQ(grid.Center().y, 0.0);
  EXPECT_DOUBLE_EQ(grid.Center().z, 2.0);
  EXPECT_TRUE(grid.Covers(bounds));
  const double outside[6] = { 0, 12, -2, 2, 1, 3 };
  EXPECT_FALSE(grid.Covers(outside));
}

TEST(VoxelGrid, SceneBoundsInWholeVoxels)
{
  // a room 10 x 6 x 10 in a grid of 11: the floor and ceiling lie 2.5 units inside the grid
  const double bounds[6] = { 0, 10, 0, 6, 0, 10 };
  VoxelGrid grid;
  ASSERT_EQ(FitVoxelGrid(bounds, 128, 0.05, grid), FitStatus::Ok);
  glm::dvec3 lo, hi;
  grid.SceneVoxels(lo, hi);
  // x: 0.5 / (11 / 128) = 5.82 -> 5, 10.5 / (11 / 128) = 122.18 -> 123
  EXPECT_DOUBLE_EQ(lo.x, 5.0);
  EXPECT_DOUBLE_EQ(hi.x, 123.0);
  // y: 2.5 / (11 / 128) = 29.09 -> 29, 8.5 / (11 / 128) = 98.9 -> 99
  EXPECT_DOUBLE_EQ(lo.y, 29.0);
  EXPECT_DOUBLE_EQ(hi.y, 99.0);
  // the scene grows within the grid: its new bounds, the grid kept
  const double grown[6] = { 0, 10, -1, 6, 0, 10 };
  grid.SetScene(grown);
  grid.SceneVoxels(lo, hi);
  EXPECT_DOUBLE_EQ(lo.y, 17.0); // 1.5 / (11 / 128) = 17.45
  // unknown or beyond the grid: the grid's faces
  VoxelGrid unknown = grid;
  unknown.SceneLo = glm::dvec3(1.0);
  unknown.SceneHi = glm::dvec3(0.0);
  unknown.SceneVoxels(lo, hi);
  EXPECT_EQ(lo, glm::dvec3(0.0));
  EXPECT_EQ(hi, glm::dvec3(128.0));
  const double beyond[6] = { -100, 100, -100, 100, -100, 100 };
  grid.SetScene(beyond);
  grid.SceneVoxels(lo, hi);
  EXPECT_EQ(lo, glm::dvec3(0.0));
  EXPECT_EQ(hi, glm::dvec3(128.0));
}

TEST(VoxelGrid, FlatSceneKeepsCubicVoxels)
{
  const double bounds[6] = { -1, 1, -3, 3, 0, 0 };
  VoxelGrid grid;
  ASSERT_EQ(FitVoxelGrid(bounds, 128, 0.0, grid), FitStatus::Ok);
  EXPECT_DOUBLE_EQ(grid.Size(), 6.0);
  EXPECT_DOUBLE_EQ(grid.Center().z, 0.0);
  EXPECT_TRUE(grid.Covers(bounds));
}

TEST(VoxelGrid, SinglePointGetsAFiniteGrid)
{
  const double bounds[6] = { 2, 2, 2, 2, 2, 2 };
  VoxelGrid grid;
  ASSERT_EQ(FitVoxelGrid(bounds, 16, 0.1, grid), FitStatus::Ok);
  EXPECT_GT(grid.VoxelSize, 0.0);
  EXPECT_TRUE(std::isfinite(grid.VoxelSize));
  EXPECT_TRUE(grid.Covers(bounds));
  EXPECT_NEAR(grid.Center().x, 2.0, 1e-12);
}

TEST(VoxelGrid, OffsetSceneKeepsPrecision)
{
  // A 1-unit scene 1e8 away from the origin: voxel coordinates must still resolve 1/128.
  const double bounds[6] = { 1e8, 1e8 + 1, 1e8, 1e8 + 1, -1e8, -1e8 + 1 };
  VoxelGrid grid;
  ASSERT_EQ(FitVoxelGrid(bounds, 128, 0.0, grid), FitStatus::Ok);
  EXPECT_DOUBLE_EQ(grid.Size(), 1.0);
  const glm::dvec3 v = grid.ToVoxel(glm::dvec3(1e8 + 0.5, 1e8 + 0.25, -1e8 + 0.75));
  EXPECT_NEAR(v.x, 64.0, 1e-5);
  EXPECT_NEAR(v.y, 32.0, 1e-5);
  EXPECT_NEAR(v.z, 96.0, 1e-5);
}

TEST(VoxelGrid, RejectsEmptyAndNonFiniteBounds)
{
  VoxelGrid grid;
  const double empty[6] = { 1, -1, 1, -1, 1, -1 };
  EXPECT_EQ(FitVoxelGrid(empty, 64, 0.05, grid), FitStatus::EmptyBounds);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double withNaN[6] = { 0, 1, nan, 1, 0, 1 };
  EXPECT_EQ(FitVoxelGrid(withNaN, 64, 0.05, grid), FitStatus::NonFiniteBounds);
  const double inf = std::numeric_limits<double>::infinity();
  const double withInf[6] = { 0, inf, 0, 1, 0, 1 };
  EXPECT_EQ(FitVoxelGrid(withInf, 64, 0.05, grid), FitStatus::NonFiniteBounds);
}

TEST(VoxelGrid, ResolutionRoundsToPowersOfTwoInRange)
{
  EXPECT_EQ(voxelgi::ClampResolution(128, 16, 512), 128);
  EXPECT_EQ(voxelgi::ClampResolution(100, 16, 512), 128);
  EXPECT_EQ(voxelgi::ClampResolution(90, 16, 512), 64);
  EXPECT_EQ(voxelgi::ClampResolution(1, 16, 512), 16);
  EXPECT_EQ(voxelgi::ClampResolution(-5, 16, 512), 16);
  EXPECT_EQ(voxelgi::ClampResolution(4096, 16, 512), 512);
}
