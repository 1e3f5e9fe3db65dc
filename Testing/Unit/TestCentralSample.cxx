// Which of a multisampled framebuffer's samples the G-buffer takes for a pixel when VTK's own
// draw stores it, and whether one lies near enough the centre for that (GBufferPass).
#include "GBufferPass.h"

#include <gtest/gtest.h>

#include <vector>

using namespace voxelgi;

namespace
{
/// Positions given in sixteenths of a pixel, as the standard patterns are published.
std::vector<float> Sixteenths(const std::vector<int>& at)
{
  std::vector<float> positions;
  for (int v : at)
  {
    positions.push_back(v / 16.f);
  }
  return positions;
}
}

TEST(CentralSample, EightSamplesHaveOneNearTheCentre)
{
  // The standard 8x pattern (NVIDIA's default): samples 0 and 1 lie sqrt(10)/16 from the
  // centre, on opposite sides; the first is taken, in every pixel.
  const std::vector<float> p =
    Sixteenths({ 9, 5, 7, 11, 13, 9, 5, 3, 3, 13, 1, 7, 11, 15, 15, 1 });
  float distance = 0.f;
  EXPECT_EQ(CentralSample(p.data(), 8, distance), 0);
  EXPECT_NEAR(distance, 0.19764f, 1e-4f);
  EXPECT_LE(distance, MaxCentralSampleDistance);
}

TEST(CentralSample, FourAndTwoSamplesHaveNone)
{
  // The standard 4x pattern (Mesa's llvmpipe among others): all four sqrt(10)/8 away.
  const std::vector<float> four = Sixteenths({ 6, 2, 14, 6, 2, 10, 10, 14 });
  float distance = 0.f;
  EXPECT_EQ(CentralSample(four.data(), 4, distance), 0);
  EXPECT_NEAR(distance, 0.39528f, 1e-4f);
  EXPECT_GT(distance, MaxCentralSampleDistance);
  const std::vector<float> two = Sixteenths({ 4, 4, 12, 12 });
  EXPECT_EQ(CentralSample(two.data(), 2, distance), 0);
  EXPECT_NEAR(distance, 0.35355f, 1e-4f);
  EXPECT_GT(distance, MaxCentralSampleDistance);
}

TEST(CentralSample, TheNearestWhereverItIs)
{
  const std::vector<float> p = { 0.9f, 0.9f, 0.1f, 0.2f, 0.5f, 0.55f, 0.45f, 0.5f };
  float distance = 1.f;
  EXPECT_EQ(CentralSample(p.data(), 4, distance), 2); // 0.05 away; the fourth ties, later
  EXPECT_NEAR(distance, 0.05f, 1e-6f);
  const std::vector<float> centre = { 0.5f, 0.5f };
  EXPECT_EQ(CentralSample(centre.data(), 1, distance), 0);
  EXPECT_EQ(distance, 0.f);
}
