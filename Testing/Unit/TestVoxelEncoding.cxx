// Averaging encode/decode: 8-bit quantization and exact 32-bit sums.
#include "VoxelEncoding.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

using namespace voxelgi;

TEST(VoxelEncoding, QuantizesToNearestOf255Levels)
{
  EXPECT_EQ(QuantizeUnit(0.0f), 0u);
  EXPECT_EQ(QuantizeUnit(1.0f), 255u);
  EXPECT_EQ(QuantizeUnit(0.5f), 128u);
  EXPECT_EQ(QuantizeUnit(100.0f / 255.0f), 100u);
  EXPECT_EQ(QuantizeUnit(-3.0f), 0u);
  EXPECT_EQ(QuantizeUnit(7.0f), 255u);
  EXPECT_EQ(QuantizeUnit(std::numeric_limits<float>::quiet_NaN()), 0u);
  EXPECT_EQ(QuantizeUnit(std::numeric_limits<float>::infinity()), 0u);
}

TEST(VoxelEncoding, MeanOfManyFragmentsIsExact)
{
  // 1000 fragments (far beyond the 255 of a packed RGBA8 running average) alternating
  // between two values: the decoded mean is their exact mean.
  std::uint32_t sum = 0;
  const std::uint32_t n = 1000;
  for (std::uint32_t i = 0; i < n; ++i)
  {
    sum += QuantizeUnit(i % 2 ? 1.0f : 0.2f);
  }
  EXPECT_NEAR(MeanFromSum(sum, n), (255.0f + 51.0f) / 2.0f / 255.0f, 1e-6f);
  EXPECT_EQ(MeanFromSum(0, 0), 0.0f);
}

TEST(VoxelEncoding, SumsDoNotOverflowWithinTheExactBound)
{
  const std::uint64_t worst = std::uint64_t(MaxExactFragmentsPerVoxel) * 255u;
  EXPECT_LE(worst, std::uint64_t(std::numeric_limits<std::uint32_t>::max()));
  EXPECT_GT(MaxExactFragmentsPerVoxel, 16000000u);
}
