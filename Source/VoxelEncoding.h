/**
 * CPU mirror of the voxel averaging in Shaders/voxel_common.glsl: values are quantized to
 * 8 bits and summed exactly in 32-bit integers per channel; the mean is sum / (255 count).
 * Used by the unit tests to check encode/decode and the overflow bound.
 */
#ifndef VoxelGIVoxelEncoding_h
#define VoxelGIVoxelEncoding_h

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace voxelgi
{

inline std::uint32_t QuantizeUnit(float v)
{
  if (!std::isfinite(v))
  {
    v = 0.0f;
  }
  return static_cast<std::uint32_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
}

inline float MeanFromSum(std::uint32_t sum, std::uint32_t count)
{
  return count ? static_cast<float>(sum) / (255.0f * static_cast<float>(count)) : 0.0f;
}

/// Fragments per voxel for which the 32-bit sums of 8-bit values are guaranteed exact.
constexpr std::uint32_t MaxExactFragmentsPerVoxel = 0xFFFFFFFFu / 255u;

}

#endif
