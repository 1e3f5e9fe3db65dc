// Shared by the voxelization fragment code (GLSL 1.50 + extensions) and the compute stages
// (GLSL 4.30). The host defines VOXELGI_EMISSION when the scene emits and
// VOXELGI_TRANSLUCENT when translucent surfaces are voxelized.
//
// Voxelization accumulates exact integer sums of 8-bit quantized values, one uint per voxel
// and channel, so the mean stays exact up to 2^32 / 255 (16.8 million) fragments per voxel
// instead of overflowing at 255 as a packed RGBA8 running average would. Emission is not
// quantized: each channel keeps the largest radiance of the voxel's emitting fragments as
// float bits (atomicMax orders non-negative floats' bits as the floats), and a fourth channel
// sums the emitting surfaces' coverage of the voxel (voxel_write.glsl), in 1/1024 units; the
// voxel emits that radiance times its covered fraction, so the conservative fringe of an
// emitter does not emit as if filled. Exact where one emitter covers the voxel, whatever its
// radiance relative to others; where emitters of different radiance share a voxel the
// brighter one counts. A translucent fragment of opacity a also adds its quantized 1 - a to
// the clearness channel: the voxel stops the share of light its fragments' mean opacity says
// (partial occupancy), so a translucent surface occludes and reflects as much as it is
// opaque, and an opaque surface in the same voxel still fills most of it.
// One buffer per channel, bound at consecutive points in this order; separate blocks rather
// than an array of blocks, which some compilers only index by literal constants.
layout(std430, binding = 0) buffer VoxelCountBuffer { uint voxelCount[]; };
layout(std430, binding = 1) buffer VoxelAlbedoRBuffer { uint voxelAlbedoR[]; };
layout(std430, binding = 2) buffer VoxelAlbedoGBuffer { uint voxelAlbedoG[]; };
layout(std430, binding = 3) buffer VoxelAlbedoBBuffer { uint voxelAlbedoB[]; };
layout(std430, binding = 4) buffer VoxelNormalXBuffer { uint voxelNormalX[]; };
layout(std430, binding = 5) buffer VoxelNormalYBuffer { uint voxelNormalY[]; };
layout(std430, binding = 6) buffer VoxelNormalZBuffer { uint voxelNormalZ[]; };
#ifdef VOXELGI_EMISSION
layout(std430, binding = 7) buffer VoxelEmissionRBuffer { uint voxelEmissionR[]; };
layout(std430, binding = 8) buffer VoxelEmissionGBuffer { uint voxelEmissionG[]; };
layout(std430, binding = 9) buffer VoxelEmissionBBuffer { uint voxelEmissionB[]; };
layout(std430, binding = 10) buffer VoxelEmissionCoverageBuffer { uint voxelEmissionCoverage[]; };
#endif
#ifdef VOXELGI_TRANSLUCENT
layout(std430, binding = VOXELGI_CLEARNESS_BINDING) buffer VoxelClearnessBuffer
{
  uint voxelClearness[];
};
#endif

#include "voxel_grid.glsl"

int voxelIndex(ivec3 v)
{
  return v.x + voxelResolution * (v.y + voxelResolution * v.z);
}

// Non-finite input counts as 0 so one bad vertex cannot poison a voxel.
uint voxelQuantize(float v)
{
  return uint(clamp((isnan(v) || isinf(v)) ? 0.0 : v, 0.0, 1.0) * 255.0 + 0.5);
}

const float voxelCoverageScale = 1024.0;

// Mean of three channel sums over `count` fragments.
vec3 voxelMean(uint r, uint g, uint b, float count)
{
  return vec3(float(r), float(g), float(b)) / (255.0 * count);
}
