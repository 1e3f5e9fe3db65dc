// The shader embedder's output: the shared interface in front of every shader (after VTK's
// `//VTK::System::Dec`, which becomes `#version`), includes expanded once, `#line`
// directives, and compiler logs that name the files.
#include "GLHelpers.h"
#include "VoxelGIShaders.h"

#include <gtest/gtest.h>

#include <string>

namespace
{
int FileNumber(const char* name)
{
  for (int i = 0; i < voxelgi::shaders::file_count; ++i)
  {
    if (std::string(voxelgi::shaders::file_names[i]) == name)
    {
      return i;
    }
  }
  return -1;
}

int Count(const std::string& text, const std::string& what)
{
  int n = 0;
  for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1))
  {
    ++n;
  }
  return n;
}
}

TEST(ShaderEmbedding, ComputeShadersStartWithTheInterface)
{
  const std::string trace = voxelgi::shaders::cone_trace_comp;
  const int interface = FileNumber("shader_interface.h");
  ASSERT_GE(interface, 0);
  EXPECT_EQ(trace.rfind("#line 1 " + std::to_string(interface) + "\n", 0), 0u);
  EXPECT_NE(trace.find("#define VOXELGI_MAX_LIGHTS 16"), std::string::npos);
  // voxel_grid.glsl is included by three of its includes, expanded once.
  EXPECT_EQ(Count(trace, "VOXELGI_UNIFORM_BLOCK(VoxelGridBlock,"), 1);
  EXPECT_EQ(Count(trace, "#include"), 0);
}

TEST(ShaderEmbedding, VTKShadersKeepTheirVersionLineFirst)
{
  const std::string present = voxelgi::shaders::present_frag;
  EXPECT_EQ(present.rfind("//VTK::System::Dec\n#line 1 ", 0), 0u);
  const std::string geometry = voxelgi::shaders::voxelize_geom;
  EXPECT_EQ(geometry.rfind("//VTK::System::Dec\n", 0), 0u);
}

TEST(ShaderEmbedding, LineDirectivesResumeAfterAnInclude)
{
  const std::string bounce = voxelgi::shaders::voxel_bounce_comp;
  const int file = FileNumber("voxel_bounce.comp");
  ASSERT_GE(file, 0);
  // voxel_bounce.comp includes lights.glsl on its line 7 and cone_tracing.glsl on line 8.
  EXPECT_NE(bounce.find("#line 1 " + std::to_string(file) + "\n"), std::string::npos);
  EXPECT_NE(bounce.find("#line 8 " + std::to_string(file) + "\n"), std::string::npos);
  EXPECT_NE(bounce.find("#line 9 " + std::to_string(file) + "\n"), std::string::npos);
}

TEST(ShaderEmbedding, CompilerLogsNameTheFiles)
{
  const int file = FileNumber("cone_tracing.glsl");
  ASSERT_GE(file, 0);
  const std::string n = std::to_string(file);
  // Mesa writes "<file>:<line>(<column>)", NVIDIA "<file>(<line>)".
  EXPECT_EQ(voxelgi::NameShaderFiles(n + ":12(3): error: x\n" + n + "(40) : error C1: y"),
    "cone_tracing.glsl:12(3): error: x\ncone_tracing.glsl(40) : error C1: y");
  EXPECT_EQ(voxelgi::NameShaderFiles("9999:1(1): error"), "9999:1(1): error");
  EXPECT_EQ(voxelgi::NameShaderFiles("no location here"), "no location here");
}
