/* The lights' uniform block (lights.glsl), filled by LightBlock.cxx. */
#ifndef VOXELGI_LIGHT_BLOCK
#define VOXELGI_LIGHT_BLOCK

#include "shader_interface.h"
#include "shader_interop.h"

VOXELGI_INTEROP_BEGIN

struct VoxelLight
{
  vec4 position;    // xyz: position (grid voxels); w: 1 positional, 0 directional
  vec4 direction;   // xyz: unit direction the light travels; w: cos(cone angle), -2 if no spot
  vec4 color;       // rgb: colour x intensity; w: spot exponent
  vec4 attenuation; // xyz: constant, linear, quadratic (world units); w: 1 for a headlight
};

VOXELGI_UNIFORM_BLOCK(VoxelLightBlock, VOXELGI_LIGHT_BLOCK_BINDING)
{
  VoxelLight voxelLights[VOXELGI_MAX_LIGHTS];
  ivec4 voxelLightInfo; // x: light count, y: two-sided lighting
};

VOXELGI_INTEROP_END

#endif
