// The trace's resolution for an image: TraceResolution, halved while the traced pixels would
// exceed MaxTraceMegapixels, never below a quarter.
#include "TraceScale.h"

#include <gtest/gtest.h>

using namespace voxelgi;

TEST(TraceScale, HalvedAboveTheLimit)
{
  EXPECT_EQ(TraceScale(1.0, 1.0, 1920, 1080), 0.5);  // 2.07 megapixels: 960 x 540 traced
  EXPECT_EQ(TraceScale(1.0, 1.0, 2560, 1440), 0.5);  // 3.69: 0.92 traced
  EXPECT_EQ(TraceScale(1.0, 1.0, 3840, 2160), 0.25); // 8.29: half would trace 2.07
  EXPECT_EQ(TraceScale(1.0, 1.0, 1921, 521), 0.5);   // just above one megapixel
}

TEST(TraceScale, KeptUpToTheLimit)
{
  EXPECT_EQ(TraceScale(1.0, 1.0, 1000, 1000), 1.0); // exactly one megapixel
  EXPECT_EQ(TraceScale(1.0, 1.0, 200, 200), 1.0);
  EXPECT_EQ(TraceScale(1.0, 1.0, 1280, 780), 1.0);
  EXPECT_EQ(TraceScale(0.5, 1.0, 1920, 1080), 0.5); // already within
  EXPECT_EQ(TraceScale(0.3, 1.0, 3840, 2160), 0.3); // 0.75 megapixels
}

TEST(TraceScale, NeverBelowAQuarter)
{
  EXPECT_EQ(TraceScale(1.0, 1.0, 7680, 4320), 0.25); // 33 megapixels: 2.07 traced
  EXPECT_EQ(TraceScale(0.4, 1.0, 3840, 2160), 0.4);  // half of it would be below 0.25
  EXPECT_EQ(TraceScale(0.25, 0.01, 1920, 1080), 0.25);
}

TEST(TraceScale, NoLimit)
{
  EXPECT_EQ(TraceScale(1.0, 0.0, 7680, 4320), 1.0);
  EXPECT_EQ(TraceScale(0.5, 0.0, 1920, 1080), 0.5);
}
