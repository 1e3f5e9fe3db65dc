// PrintSelf of the settings: enumerations by their names, booleans as On/Off, numbers as
// numbers, one line each.
#include "vtkVoxelGIPass.h"

#include "vtkNew.h"

#include <gtest/gtest.h>

#include <sstream>

TEST(SettingsPrint, NamesEnumerationsAndBooleans)
{
  vtkNew<vtkVoxelGIPass> pass;
  pass->SetUpdatePolicy(vtkVoxelGIPass::UPDATE_EVERY_N_FRAMES);
  pass->SetLightOcclusion(vtkVoxelGIPass::LIGHT_OCCLUSION_VOXEL_SHADOWS);
  pass->EnabledOff();
  pass->SetVoxelResolution(64);
  std::ostringstream printed;
  pass->Print(printed);
  const std::string text = printed.str();
  for (const char* line : { "UpdatePolicy: EveryNFrames (2)\n", "LightOcclusion: VoxelShadows (1)\n",
         "Enabled: Off\n", "TemporalReuse: On\n", "VoxelResolution: 64\n" })
  {
    EXPECT_NE(text.find(line), std::string::npos) << line << "not in:\n" << text;
  }
}
