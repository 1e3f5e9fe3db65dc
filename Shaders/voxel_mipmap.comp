// Anisotropic mipmaps: one level of the six directional volumes (indexed by the direction a
// cone travels) from the level below, or from the radiance volume for level 0. Along each
// direction the two voxels of a 2x2x2 block are composited front to back (volumetric
// integration), then the four results are averaged over the part of the block's
// cross-section inside the scene's bounds.
//
// Above level 0 the two texels of a column are themselves averages over 2x2 (or more)
// columns. A surface's share of them is coverage of the same columns in both (a solid block,
// a wall seen along its plane): composited as independent, a 4-voxel block would cover 1.75x
// its area at the 16-voxel level and a small emitter would shine that much brighter, so the
// back adds only the coverage the front leaves (max). A translucent medium's share (a volume,
// a translucent surface: voxels of partial occupancy) does attenuate layer after layer, so it
// keeps the independent composite; the two are blended by the medium's share of the block's
// occupancy, kept in its own volume beside the directional ones (only for scenes with media).
layout(local_size_x = VOXELGI_LOCAL_SIZE, local_size_y = VOXELGI_LOCAL_SIZE, local_size_z = VOXELGI_LOCAL_SIZE) in;

#include "voxel_grid.glsl"

uniform sampler3D voxelRadiance;
uniform sampler3D voxelNormal; // unit normal (rgb), a surface (a > 0)
uniform sampler3D voxelDirect; // a < 0: the lights reach the back of the winding
uniform int litSides;          // 1: voxelDirect says which side is lit
uniform sampler3D voxelPosX;
uniform sampler3D voxelNegX;
uniform sampler3D voxelPosY;
uniform sampler3D voxelNegY;
uniform sampler3D voxelPosZ;
uniform sampler3D voxelNegZ;
uniform int sourceIsRadiance; // 1: build level 0 from the radiance volume
uniform int sourceLevel;      // otherwise: the directional level to read
uniform int targetSize;       // voxels per axis of the level being written
uniform int media;            // 1: the scene has voxels of partial occupancy (voxelMedium)
uniform sampler3D voxelMedium; // mean occupancy of partial (r) and full (g) voxels, per level
layout(rgba16f, binding = 0) uniform writeonly image3D outPosX;
layout(rgba16f, binding = 1) uniform writeonly image3D outNegX;
layout(rgba16f, binding = 2) uniform writeonly image3D outPosY;
layout(rgba16f, binding = 3) uniform writeonly image3D outNegY;
layout(rgba16f, binding = 4) uniform writeonly image3D outPosZ;
layout(rgba16f, binding = 5) uniform writeonly image3D outNegZ;
layout(rg8, binding = 6) uniform writeonly image3D outMedium;

const vec3 travel[6] = vec3[6](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0),
  vec3(0, 0, 1), vec3(0, 0, -1));

// A surface's voxel sends its light to the side the lights reach: a cone travelling along d
// sees all of it from the front and edge on, none from behind (a table lit from above does
// not light the floor under it), over a ramp of 0.5 in the cosine. It still blocks either
// way. Voxels without a normal (volumes, opposing faces) send it every way, and so does every
// voxel where no lit side was recorded (no bounces: a room wound outward would go dark).
vec4 fetchRadiance(int direction, ivec3 c)
{
  vec4 radiance = texelFetch(voxelRadiance, c, 0);
  vec4 normal = texelFetch(voxelNormal, c, 0);
  vec3 n = normal.xyz * 2.0 - 1.0;
  if (litSides == 0 || radiance.a == 0.0 || normal.a == 0.0 || dot(n, n) < 0.25)
  {
    return radiance;
  }
  float side = texelFetch(voxelDirect, c, 0).a;
  if (abs(side) < 0.75)
  {
    return radiance; // no light reaches it: which side is lit is not known
  }
  float facing = dot(normalize(n) * sign(side), travel[direction]);
  return vec4(radiance.rgb * clamp(1.0 - 2.0 * facing, 0.0, 1.0), radiance.a);
}

vec4 fetchSource(int direction, ivec3 c)
{
  if (sourceIsRadiance != 0)
  {
    return fetchRadiance(direction, c);
  }
  if (direction == 0) return texelFetch(voxelPosX, c, sourceLevel);
  if (direction == 1) return texelFetch(voxelNegX, c, sourceLevel);
  if (direction == 2) return texelFetch(voxelPosY, c, sourceLevel);
  if (direction == 3) return texelFetch(voxelNegY, c, sourceLevel);
  if (direction == 4) return texelFetch(voxelPosZ, c, sourceLevel);
  return texelFetch(voxelNegZ, c, sourceLevel);
}

// Direction d travels along `axis`, positive when `positive`: the voxel with the smaller
// coordinate on that axis is in front for positive travel. `medium`: the block's share of
// occupancy that partial voxels hold. Columns wholly outside the scene's bounds (the grid's
// empty margin) are left out of the average: a cone travelling along a room's floor reads the
// side walls in texels that reach past the floor, and diluted by that margin they would let
// it leave the room.
vec4 integrate(int direction, ivec3 base, int axis, bool positive, float medium)
{
  vec4 sum = vec4(0.0);
  float count = 0.0;
  vec3 texel = vec3(sourceIsRadiance != 0 ? 1.0 : exp2(float(sourceLevel + 1)));
  vec3 span = texel;
  span[axis] *= 2.0;
  for (int i = 0; i < 2; ++i)
  {
    for (int j = 0; j < 2; ++j)
    {
      ivec3 a = base;
      ivec3 b = base;
      if (axis == 0) { a += ivec3(0, i, j); b += ivec3(1, i, j); }
      else if (axis == 1) { a += ivec3(i, 0, j); b += ivec3(i, 1, j); }
      else { a += ivec3(i, j, 0); b += ivec3(i, j, 1); }
      vec3 lo = vec3(a) * texel;
      if (any(greaterThanEqual(lo, voxelSceneHi.xyz)) || any(lessThanEqual(lo + span, voxelSceneLo.xyz)))
      {
        continue;
      }
      vec4 front = fetchSource(direction, positive ? a : b);
      vec4 back = fetchSource(direction, positive ? b : a);
      vec4 independent = front + (1.0 - front.a) * back;
      float covered = max(front.a, back.a);
      vec4 correlated = vec4(front.rgb + (back.a > 0.0 ? (covered - front.a) / back.a : 0.0) * back.rgb, covered);
      sum += sourceIsRadiance != 0 ? independent : mix(correlated, independent, medium);
      count += 1.0;
    }
  }
  return count > 0.0 ? sum / count : vec4(0.0);
}

// The medium's share of the block's occupancy, and (media) its own level written.
float mediumShare(ivec3 base, ivec3 v)
{
  if (media == 0)
  {
    return 0.0;
  }
  vec2 sum = vec2(0.0);
  for (int k = 0; k < 8; ++k)
  {
    ivec3 c = base + ivec3(k & 1, (k >> 1) & 1, k >> 2);
    if (sourceIsRadiance != 0)
    {
      float a = texelFetch(voxelRadiance, c, 0).a;
      sum += a >= 0.999 ? vec2(0.0, 1.0) : vec2(a, 0.0);
    }
    else
    {
      sum += texelFetch(voxelMedium, c, sourceLevel).rg;
    }
  }
  sum *= 0.125;
  imageStore(outMedium, v, vec4(sum, 0.0, 0.0));
  return sum.r + sum.g > 0.0 ? sum.r / (sum.r + sum.g) : 0.0;
}

void main()
{
  ivec3 v = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(v, ivec3(targetSize))))
  {
    return;
  }
  ivec3 base = v * 2;
  float medium = mediumShare(base, v);
  imageStore(outPosX, v, integrate(0, base, 0, true, medium));
  imageStore(outNegX, v, integrate(1, base, 0, false, medium));
  imageStore(outPosY, v, integrate(2, base, 1, true, medium));
  imageStore(outNegY, v, integrate(3, base, 1, false, medium));
  imageStore(outPosZ, v, integrate(4, base, 2, true, medium));
  imageStore(outNegZ, v, integrate(5, base, 2, false, medium));
}
