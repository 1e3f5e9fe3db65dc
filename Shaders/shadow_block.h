/* The shadow maps' uniform block (shadow_maps.glsl), filled by ShadowMaps.cxx. Light indices
   are the light block's (light_block.h). */
#ifndef VOXELGI_SHADOW_BLOCK
#define VOXELGI_SHADOW_BLOCK

#include "shader_interface.h"
#include "shader_interop.h"

VOXELGI_INTEROP_BEGIN

VOXELGI_UNIFORM_BLOCK(VoxelShadowBlock, VOXELGI_SHADOW_BLOCK_BINDING)
{
  mat4 shadowMatrices[VOXELGI_MAX_SHADOW_LAYERS]; // grid coordinates -> a layer's clip space
  // x: first layer (-1: no map), y: layers (1, or 6 for a point light: +x -x +y -y +z -z),
  // z: 1 when the map stays valid for the pixels between relights (a scene light; a camera
  // light's map lags while it turns)
  ivec4 shadowLights[VOXELGI_MAX_LIGHTS];
  // x + y * distance from the light: a map texel's width in voxels there
  vec4 shadowTexels[VOXELGI_MAX_LIGHTS];
  // x: 1 when every light that casts shadows (every light but a headlight) has maps valid
  // for the pixels; y: 1 when the layers have translucent casters' transmittance
  ivec4 shadowInfo;
};

VOXELGI_INTEROP_END

#endif
