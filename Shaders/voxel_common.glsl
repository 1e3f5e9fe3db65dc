// Shared by the voxelization fragment code (GLSL 1.50 + extensions) and the compute stages
// (GLSL 4.30). VOXEL_CHANNELS is defined by the host: 7 without emission, 10 with it.
//
// Voxelization accumulates exact integer sums of 8-bit quantized values, one uint per voxel
// and channel, so the mean stays exact up to 2^32 / 255 (16.8 million) fragments per voxel
// instead of overflowing at 255 as a packed RGBA8 running average would.
#define VOXEL_COUNT 0
#define VOXEL_ALBEDO 1
#define VOXEL_NORMAL 4
#define VOXEL_EMISSION 7

layout(std430, binding = 0) buffer VoxelAccumulator
{
  uint value[];
} voxelAccum[VOXEL_CHANNELS];

uniform int voxelResolution;

int voxelIndex(ivec3 v)
{
  return v.x + voxelResolution * (v.y + voxelResolution * v.z);
}

// Non-finite input counts as 0 so one bad vertex cannot poison a voxel.
uint voxelQuantize(float v)
{
  return uint(clamp((isnan(v) || isinf(v)) ? 0.0 : v, 0.0, 1.0) * 255.0 + 0.5);
}

// Mean of three consecutive channels; a macro because block array indices must be constant.
#define VOXEL_MEAN(index, channel, count)                                                        \
  (vec3(float(voxelAccum[channel].value[index]), float(voxelAccum[channel + 1].value[index]),     \
     float(voxelAccum[channel + 2].value[index])) / (255.0 * (count)))
