// The software profile: which GL_RENDERER strings name a CPU renderer, when the profile
// applies, and what it caps.
#include "SoftwareProfile.h"

#include <gtest/gtest.h>

using namespace voxelgi;

TEST(SoftwareProfile, NamesCpuRenderers)
{
  for (const char* cpu : { "llvmpipe (LLVM 15.0.6, 256 bits)", "softpipe",
         "SWR (LLVM 12.0.0, 256 bits)", "SwiftShader Device (Subzero) (0x0000C0DE)", "GDI Generic",
         "Microsoft Basic Render Driver", "Software Rasterizer" })
  {
    EXPECT_TRUE(IsSoftwareRenderer(cpu)) << cpu;
  }
  for (const char* gpu : { "NVIDIA H200/PCIe/SSE2",
         "AMD Radeon RX 6800 XT (radeonsi, navi21, LLVM 15.0.6, DRM 3.49)",
         "Mesa Intel(R) UHD Graphics 620 (KBL GT2)", "Apple M2", "" })
  {
    EXPECT_FALSE(IsSoftwareRenderer(gpu)) << gpu;
  }
}

TEST(SoftwareProfile, Applies)
{
  EXPECT_TRUE(SoftwareProfileApplies(SOFTWARE_PROFILE_AUTO, true));
  EXPECT_FALSE(SoftwareProfileApplies(SOFTWARE_PROFILE_AUTO, false));
  EXPECT_TRUE(SoftwareProfileApplies(SOFTWARE_PROFILE_ON, false));
  EXPECT_FALSE(SoftwareProfileApplies(SOFTWARE_PROFILE_OFF, true));
}

TEST(SoftwareProfile, CapsTheDefaultsAndKeepsLowerValues)
{
  Settings defaults;
  ApplySoftwareProfile(defaults);
  EXPECT_EQ(defaults.VoxelResolution, 64);
  EXPECT_EQ(defaults.DiffuseConeCount, 4);
  EXPECT_EQ(defaults.TraceResolution, 0.25);
  EXPECT_EQ(defaults.ShadowMapResolution, 256);
  EXPECT_EQ(defaults.Bounces, 3); // bounces are kept

  Settings small;
  small.VoxelResolution = 32;
  small.DiffuseConeCount = 1;
  small.ShadowMapResolution = 128;
  ApplySoftwareProfile(small);
  EXPECT_EQ(small.VoxelResolution, 32);
  EXPECT_EQ(small.DiffuseConeCount, 1);
  EXPECT_EQ(small.ShadowMapResolution, 128);
}
