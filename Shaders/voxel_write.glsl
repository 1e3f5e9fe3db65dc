// The voxel writes of voxelization, shared by the fragment code injected into VTK's mappers
// (voxelize.frag) and the compute path (voxelize.comp): one pixel column of a triangle's
// dominant-axis projection (voxel_triangle.glsl) adds the triangle's colour, normal and
// emission to every voxel of the column it may touch.
#include "voxel_common.glsl"

uniform int voxelStaticPass;  // 1: marks the flag volume; 0: dynamic, leaves static voxels alone
uniform vec3 voxelEmission;   // this actor's emitted radiance (finite, non-negative)
layout(r8ui, binding = VOXELGI_FLAG_IMAGE_UNIT) uniform uimage3D voxelFlag;

const float voxelEps = 1e-3;

// Does the pixel square centred on c reach the inside of this edge's half plane?
bool voxelEdgeReaches(vec3 e, vec2 c)
{
  return dot(e.xy, c) + e.z <= 0.5 * (abs(e.x) + abs(e.y)) + voxelEps * length(e.xy);
}

ivec3 voxelUnswizzle(ivec3 q, int axis)
{
  return axis == 0 ? q.zxy : (axis == 1 ? q.yzx : q);
}

// The fraction of the pixel square centred on c inside this edge's half plane: exact for
// axis-aligned edges, linear in the edge function between the square's extremes otherwise.
// Two triangles sharing the edge get fractions that sum to 1.
float voxelEdgeCoverage(vec3 e, vec2 c)
{
  float reach = abs(e.x) + abs(e.y);
  return clamp(0.5 - (dot(e.xy, c) + e.z) / reach, 0.0, 1.0);
}

// The share of the triangle's projected coverage in the voxel of depth k, from where the
// plane's depth interval over the pixel square [lo, hi] meets [k, k + 1]. A plane along
// the voxels' faces covers each voxel it lies in, both where it lies on their boundary (a
// wall between two layers is seen from each side in the layer on that side).
float voxelDepthShare(float lo, float hi, int k)
{
  if (hi - lo < 1e-4)
  {
    float z = 0.5 * (lo + hi);
    return abs(clamp(z, float(k), float(k + 1)) - z) <= voxelEps ? 1.0 : 0.0;
  }
  return max(min(hi, float(k + 1)) - max(lo, float(k)), 0.0) / (hi - lo);
}

// `coverage`: the fraction of the voxel's cross-section along the triangle's projection axis
// that the triangle covers; it weighs only emission (voxel_common.glsl).
void voxelStore(ivec3 v, vec4 color, vec3 faceNormal, float coverage)
{
#ifdef VOXELGI_TRANSLUCENT
  // (a fragment a lookup table hides takes no part: VTK shows what lies behind it)
  uint clearness = 255u - voxelQuantize(color.a);
  if (clearness == 255u)
  {
    return;
  }
#endif
  if (voxelStaticPass != 0)
  {
    imageStore(voxelFlag, v, uvec4(1u));
  }
  else if (imageLoad(voxelFlag, v).r != 0u)
  {
    return;
  }
  int i = voxelIndex(v);
  vec3 n = faceNormal * 0.5 + 0.5;
  atomicAdd(voxelCount[i], 1u);
  atomicAdd(voxelAlbedoR[i], voxelQuantize(color.r));
  atomicAdd(voxelAlbedoG[i], voxelQuantize(color.g));
  atomicAdd(voxelAlbedoB[i], voxelQuantize(color.b));
  atomicAdd(voxelNormalX[i], voxelQuantize(n.x));
  atomicAdd(voxelNormalY[i], voxelQuantize(n.y));
  atomicAdd(voxelNormalZ[i], voxelQuantize(n.z));
#ifdef VOXELGI_TRANSLUCENT
  if (clearness > 0u)
  {
    atomicAdd(voxelClearness[i], clearness);
  }
#endif
#ifdef VOXELGI_EMISSION
  vec3 e = clamp(voxelEmission, 0.0, VOXELGI_HALF_MAX);
  if (any(greaterThan(e, vec3(0.0))))
  {
    atomicMax(voxelEmissionR[i], floatBitsToUint(e.r));
    atomicMax(voxelEmissionG[i], floatBitsToUint(e.g));
    atomicMax(voxelEmissionB[i], floatBitsToUint(e.b));
    atomicAdd(voxelEmissionCoverage[i], uint(coverage * voxelCoverageScale + 0.5));
  }
#endif
}

// Writes every voxel of the pixel column centred on `c` that the triangle may touch: the
// pixel square must overlap the triangle's projection (bounding box and the three edges), and
// the voxel's depth interval must meet the triangle plane's depth over the square, within the
// triangle's depth range. A superset of the exact triangle/box overlap, so no touched voxel is
// missed.
void voxelWriteColumn(VoxelTriangle t, vec2 c, vec4 color)
{
  if (any(lessThan(c + 0.5 + voxelEps, t.box.xy)) ||
    any(greaterThan(c - 0.5 - voxelEps, t.box.zw)))
  {
    return;
  }
  if (!voxelEdgeReaches(t.edge0, c) || !voxelEdgeReaches(t.edge1, c) ||
    !voxelEdgeReaches(t.edge2, c))
  {
    return;
  }
  float zc = dot(t.plane.xy, c) + t.plane.z;
  float dz = 0.5 * (abs(t.plane.x) + abs(t.plane.y));
  float zlo = max(zc - dz, t.depthRange.x) - voxelEps;
  float zhi = min(zc + dz, t.depthRange.y) + voxelEps;
  ivec2 xy = ivec2(floor(c));
  if (any(lessThan(xy, ivec2(0))) || any(greaterThanEqual(xy, ivec2(voxelResolution))))
  {
    return;
  }
  int k0 = max(int(floor(zlo)), 0);
  int k1 = min(int(floor(zhi)), voxelResolution - 1);
  // Clipped to the triangle's bounds, so a sliver or a triangle smaller than the pixel does
  // not count as covering it.
  vec2 boxOverlap = max(min(c + 0.5, t.box.zw) - max(c - 0.5, t.box.xy), vec2(0.0));
  float coverage = min(voxelEdgeCoverage(t.edge0, c) * voxelEdgeCoverage(t.edge1, c) *
      voxelEdgeCoverage(t.edge2, c), boxOverlap.x * boxOverlap.y);
  float depthLo = max(zc - dz, t.depthRange.x);
  float depthHi = min(zc + dz, t.depthRange.y);
  // The dominant-axis projection bounds the depth slope by 1 per axis: at most 3 voxels.
  for (int k = k0; k <= k1 && k <= k0 + 3; ++k)
  {
    voxelStore(voxelUnswizzle(ivec3(xy, k), t.axis), color, t.faceNormal,
      coverage * voxelDepthShare(depthLo, depthHi, k));
  }
}
