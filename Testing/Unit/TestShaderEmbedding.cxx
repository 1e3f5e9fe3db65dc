// The shader embedder's output: the shared interface in front of every shader (after VTK's
// `//VTK::System::Dec`, which becomes `#version`), includes expanded once, `#line`
// directives, and compiler logs that name the files. The uniform blocks declared once for C++
// and GLSL (Shaders/*_block.h): the C++ structs have the std140 layout (offsets worked out by
// hand below from the std140 rules, not from sizeof), and every embedded shader that reads a
// block has the shared header's declaration of it, once, and no other.
#include "GLHelpers.h"
#include "VoxelGIShaders.h"
#include "light_block.h"
#include "shadow_block.h"
#include "voxel_grid_block.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

namespace
{
using namespace voxelgi::glsl;

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

struct Shader
{
  const char* Name;
  std::string Text;
};

std::vector<Shader> EmbeddedShaders()
{
  namespace s = voxelgi::shaders;
  return { { "clear_dynamic.comp", s::clear_dynamic_comp }, { "composite.comp", s::composite_comp },
    { "cone_trace.comp", s::cone_trace_comp }, { "debug_view.comp", s::debug_view_comp },
    { "gbuffer.frag", s::gbuffer_frag }, { "light_voxels.comp", s::light_voxels_comp },
    { "present.frag", s::present_frag }, { "voxel_bounce.comp", s::voxel_bounce_comp },
    { "voxel_mipmap.comp", s::voxel_mipmap_comp }, { "voxel_resolve.comp", s::voxel_resolve_comp },
    { "voxelize_volume.comp", s::voxelize_volume_comp },
    { "voxelize.frag", s::voxelize_frag }, { "voxelize.geom", s::voxelize_geom } };
}

// `block` (declared in `header` with binding `binding`) is in every embedded shader that reads
// one of `members`, once, as the header declares it; returns how many shaders read it.
int ExpectSharedDeclaration(const char* header, const std::string& block, const char* binding,
  const std::vector<std::string>& members)
{
  const int file = FileNumber(header);
  EXPECT_GE(file, 0) << header << " is in no embedded shader";
  const std::string declaration = "VOXELGI_UNIFORM_BLOCK(" + block + ", " + binding + ")";
  int readers = 0;
  for (const Shader& shader : EmbeddedShaders())
  {
    bool reads = false;
    for (const std::string& member : members)
    {
      reads = reads || shader.Text.find(member) != std::string::npos;
    }
    if (!reads)
    {
      EXPECT_EQ(Count(shader.Text, declaration), 0) << shader.Name;
      continue;
    }
    ++readers;
    EXPECT_EQ(Count(shader.Text, declaration), 1) << shader.Name << " lacks " << block;
    // The text that follows the header's first #line is the header.
    const auto start = shader.Text.find("#line 1 " + std::to_string(file) + "\n");
    EXPECT_NE(start, std::string::npos) << shader.Name << " lacks " << header;
    EXPECT_LT(start, shader.Text.find(declaration)) << shader.Name;
    // No second declaration written out by hand, and the GLSL reading of the macro.
    EXPECT_EQ(Count(shader.Text, "uniform " + block), 0) << shader.Name;
    EXPECT_EQ(Count(shader.Text,
                "#define VOXELGI_UNIFORM_BLOCK(name, point) layout(std140, binding = point) "
                "uniform name\n"),
      1)
      << shader.Name;
    // shader_interface.h, which the block headers include for C++, only once in front.
    EXPECT_EQ(Count(shader.Text, "#define VOXELGI_SHADER_INTERFACE\n"), 1) << shader.Name;
    EXPECT_EQ(Count(shader.Text, "#include"), 0) << shader.Name;
  }
  return readers;
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
  // voxel_bounce.comp includes lights.glsl on its line 11 and cone_tracing.glsl on line 12.
  EXPECT_NE(bounce.find("#line 1 " + std::to_string(file) + "\n"), std::string::npos);
  EXPECT_NE(bounce.find("#line 12 " + std::to_string(file) + "\n"), std::string::npos);
  EXPECT_NE(bounce.find("#line 13 " + std::to_string(file) + "\n"), std::string::npos);
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

// The literals assume these counts.
static_assert(VOXELGI_MAX_LIGHTS == 16 && VOXELGI_MAX_SHADOW_LAYERS == 96, "update the literals");

TEST(ShaderBlocks, TypesHaveStd140Sizes)
{
  // vec4, ivec4: base alignment and size 16; mat4: four column vec4s, column-major.
  EXPECT_EQ(sizeof(vec4), 16u);
  EXPECT_EQ(alignof(vec4), 16u);
  EXPECT_EQ(sizeof(ivec4), 16u);
  EXPECT_EQ(alignof(ivec4), 16u);
  EXPECT_EQ(sizeof(mat4), 64u);
  mat4 m{};
  EXPECT_EQ(reinterpret_cast<const char*>(&m[1][2]) - reinterpret_cast<const char*>(&m), 24);
}

TEST(ShaderBlocks, VoxelGridBlockIsStd140)
{
  // int at 0, float at 4 (base alignment 4 each); the vec4s at the next multiples of 16.
  EXPECT_EQ(offsetof(VoxelGridBlock, voxelResolution), 0u);
  EXPECT_EQ(offsetof(VoxelGridBlock, voxelSize), 4u);
  EXPECT_EQ(offsetof(VoxelGridBlock, voxelSceneLo), 16u);
  EXPECT_EQ(offsetof(VoxelGridBlock, voxelSceneHi), 32u);
  EXPECT_EQ(sizeof(VoxelGridBlock), 48u);
}

TEST(ShaderBlocks, VoxelLightBlockIsStd140)
{
  // VoxelLight: four vec4s at 0, 16, 32, 48 = 64 bytes (a multiple of 16: its array stride).
  EXPECT_EQ(offsetof(VoxelLight, position), 0u);
  EXPECT_EQ(offsetof(VoxelLight, direction), 16u);
  EXPECT_EQ(offsetof(VoxelLight, color), 32u);
  EXPECT_EQ(offsetof(VoxelLight, attenuation), 48u);
  EXPECT_EQ(sizeof(VoxelLight), 64u);
  // voxelLights[16]: 16 x 64 = 1024 bytes; voxelLightInfo (ivec4) at 1024, ends at 1040.
  EXPECT_EQ(offsetof(VoxelLightBlock, voxelLights), 0u);
  EXPECT_EQ(offsetof(VoxelLightBlock, voxelLightInfo), 1024u);
  EXPECT_EQ(sizeof(VoxelLightBlock), 1040u);
}

TEST(ShaderBlocks, VoxelShadowBlockIsStd140)
{
  // shadowMatrices[96]: 96 x 64 = 6144 bytes; shadowLights[16] (ivec4) 256 bytes from 6144;
  // shadowTexels[16] (vec4) 256 bytes from 6400; shadowInfo (ivec4) at 6656, ends at 6672.
  EXPECT_EQ(offsetof(VoxelShadowBlock, shadowMatrices), 0u);
  EXPECT_EQ(offsetof(VoxelShadowBlock, shadowLights), 6144u);
  EXPECT_EQ(offsetof(VoxelShadowBlock, shadowTexels), 6400u);
  EXPECT_EQ(offsetof(VoxelShadowBlock, shadowInfo), 6656u);
  EXPECT_EQ(sizeof(VoxelShadowBlock), 6672u);
}

TEST(ShaderBlocks, ShadersHaveTheSharedDeclarations)
{
  const int grid = ExpectSharedDeclaration("voxel_grid_block.h", "VoxelGridBlock",
    "VOXELGI_GRID_BLOCK_BINDING", { "voxelResolution", "voxelSize" });
  const int lights = ExpectSharedDeclaration("light_block.h", "VoxelLightBlock",
    "VOXELGI_LIGHT_BLOCK_BINDING", { "voxelLights", "voxelLightInfo" });
  const int shadows = ExpectSharedDeclaration("shadow_block.h", "VoxelShadowBlock",
    "VOXELGI_SHADOW_BLOCK_BINDING", { "shadowMatrices", "shadowLights", "shadowInfo" });
  // The voxelization, the voxel stages and the trace read the grid; the lighting, the bounce
  // and the trace the lights; the lighting and the trace the shadow maps.
  EXPECT_GE(grid, 8);
  EXPECT_EQ(lights, 3);
  EXPECT_EQ(shadows, 2);
  // The light struct comes with its block.
  const std::string trace = voxelgi::shaders::cone_trace_comp;
  EXPECT_EQ(Count(trace, "struct VoxelLight\n"), 1);
}
