// One bounce of indirect diffuse light per occupied voxel (over the occupied bricks): cones
// over the lit side's hemisphere (light_voxels.comp; six axis cones where normals cancel)
// gather the previous radiance from the mipmaps; radiance = direct + albedo x gathered. Cone
// weights sum to one, albedo is below one: repeated bounces converge from below (energy bounded).
// The last bounce may add the tail of the series it leaves out (BounceTail): each bounce sums
// the grid's increment per channel; in a closed room successive increments fall by a nearly
// constant ratio r (the albedo the light meets), so the rest of the series is the last
// increment times r / (1 - r).
layout(local_size_x = VOXELGI_LOCAL_SIZE, local_size_y = VOXELGI_LOCAL_SIZE, local_size_z = VOXELGI_LOCAL_SIZE) in;

#include "lights.glsl"
#include "cone_tracing.glsl"
#include "brick_list.glsl"

uniform sampler3D voxelAlbedo;
uniform sampler3D voxelNormal;
uniform sampler3D voxelDirect;
uniform vec3 coneDirections[VOXELGI_MAX_CONES]; // tangent space (z along the normal), cosine distributed
uniform int coneCount;
uniform float coneTanHalf;
uniform float maxDistance;
uniform int bounceIndex; // 1, 2, ... within this relight
uniform bool bounceSums; // sum the increments: a later bounce of this relight adds the tail
uniform bool bounceTail; // this is the last bounce: add the tail
// Each invocation reads its own voxel's last radiance before writing the new one.
layout(rgba16f, binding = 0) uniform restrict image3D radianceOut;
// Sums in fixed point (1 / 65536), 64 bits as low and high words: integer atomics add without
// the retries a float compare-and-swap loop costs when every work group adds to one address.
layout(std430, binding = VOXELGI_BOUNCE_SUMS_BINDING) restrict buffer BounceSums
{
  uint increments[6 * VOXELGI_MAX_BOUNCES]; // bounce k, channel c: low word at 6 (k - 1) + 2 c
  uint tailRatio[3];                         // float bits: the ratio of the last relight's tail
};
#ifdef VOXELGI_VOLUMES
// The light arriving at voxels without a normal (a volume's: isotropic), which VTK's volume
// shading adds (VolumeLighting); zero elsewhere in the occupied bricks.
layout(r11f_g11f_b10f, binding = 1) uniform writeonly image3D incidentOut;
#endif


const float sumScale = 65536.0;

vec3 bounceSum(int bounce)
{
  vec3 sum;
  for (int c = 0; c < 3; ++c)
  {
    int i = 6 * (bounce - 1) + 2 * c;
    sum[c] = (float(increments[i + 1]) * 4294967296.0 + float(increments[i])) / sumScale;
  }
  return sum;
}

// The tail's factor r / (1 - r) per channel: r from this relight's last two increments when
// it has them, else the ratio a relight measured last (a one-bounce relight continues one).
vec3 tailFactor()
{
  vec3 r;
  if (bounceIndex < 3)
  {
    r = uintBitsToFloat(uvec3(tailRatio[0], tailRatio[1], tailRatio[2]));
  }
  else
  {
    vec3 last = bounceSum(bounceIndex - 1), before = bounceSum(bounceIndex - 2);
    r = mix(vec3(0.0), last / max(before, vec3(1e-30)), greaterThan(before, vec3(0.0)));
    if (gl_WorkGroupID.x == 0u && gl_LocalInvocationIndex == 0u)
    {
      tailRatio[0] = floatBitsToUint(r.r);
      tailRatio[1] = floatBitsToUint(r.g);
      tailRatio[2] = floatBitsToUint(r.b);
    }
  }
  // at most 0.9: a room of albedo near one would otherwise have no finite tail
  r = clamp(r, vec3(0.0), vec3(0.9));
  return r / (1.0 - r);
}

// One voxel's bounce; returns its increment (new radiance minus last), zero where empty.
vec3 bounceVoxel(ivec3 v)
{
  int res = voxelResolution;
  if (any(greaterThanEqual(v, ivec3(res))))
  {
    return vec3(0.0);
  }
  vec4 albedo = texelFetch(voxelAlbedo, v, 0);
#ifdef VOXELGI_VOLUMES
  imageStore(incidentOut, v, vec4(0.0));
#endif
  if (albedo.a == 0.0)
  {
    return vec3(0.0);
  }
  vec4 direct = texelFetch(voxelDirect, v, 0);
  vec3 n = texelFetch(voxelNormal, v, 0).xyz * 2.0 - 1.0;
  vec3 p = vec3(v) + 0.5;
  vec3 gathered = vec3(0.0);
  float ignored;
  bool isotropic = dot(n, n) < 0.25;
  if (isotropic)
  {
    const vec3 axes[6] = vec3[6](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0),
      vec3(0, 0, 1), vec3(0, 0, -1));
    for (int i = 0; i < 6; ++i)
    {
      gathered += voxelConeTrace(p + axes[i], axes[i], coneTanHalf, 1.0, maxDistance, 0.0, p, vec3(0.0), ignored).rgb;
    }
    gathered /= 6.0;
  }
  else
  {
    n = normalize(n) * sign(direct.a); // over the side the lights reach (light_voxels.comp)
    vec3 t, b;
    voxelBasis(n, t, b);
    for (int i = 0; i < coneCount; ++i)
    {
      vec3 d = normalize(coneDirections[i].x * t + coneDirections[i].y * b + coneDirections[i].z * n);
      // The voxel's surface lies within half a voxel of its centre: its voxels reach at most
      // a voxel above p + n / 2, the plane the cone tracer keeps its samples clear of.
      gathered += voxelConeTrace(p + n * 1.5, d, coneTanHalf, 1.0, maxDistance, 0.0, p + 0.5 * n, n, ignored).rgb;
    }
    gathered /= float(coneCount);
  }
  // premultiplied by the occupancy (light_voxels.comp)
  vec3 reflectance = albedo.a * albedo.rgb;
  vec3 radiance = direct.rgb + reflectance * gathered;
  vec3 increment = radiance - imageLoad(radianceOut, v).rgb;
  vec3 tail = vec3(0.0);
  if (bounceTail)
  {
    tail = increment * tailFactor();
    // never below the direct light: a relight that continues a brighter solution decreases
    radiance = max(radiance + tail, direct.rgb);
  }
#ifdef VOXELGI_VOLUMES
  if (isotropic)
  {
    // The light arriving continues its series as the radiance it makes does: the tail is
    // reflectance x the incident light's own (bounded where the reflectance is near zero).
    vec3 incident = max(gathered + tail / max(reflectance, vec3(1e-3)), vec3(0.0));
    imageStore(incidentOut, v, vec4(incident, 0.0));
  }
#endif
  imageStore(radianceOut, v, vec4(min(radiance, vec3(VOXELGI_HALF_MAX)), albedo.a));
  return increment;
}

const uint groupSize = uint(VOXELGI_LOCAL_SIZE * VOXELGI_LOCAL_SIZE * VOXELGI_LOCAL_SIZE);
shared vec3 groupIncrement[groupSize];

// Adds a non-negative value to a 64-bit fixed-point sum: the low word's carry goes to the high.
void addIncrement(int index, float value)
{
  float scaled = max(value, 0.0) * sumScale;
  float high = floor(scaled / 4294967296.0);
  uint low = uint(scaled - high * 4294967296.0);
  uint before = atomicAdd(increments[index], low);
  atomicAdd(increments[index + 1], uint(high) + (before + low < before ? 1u : 0u));
}

void main()
{
  vec3 increment = bounceVoxel(voxelBrickInvocation()); // occupied bricks only
  if (!bounceSums)
  {
    return;
  }
  uint i = gl_LocalInvocationIndex;
  groupIncrement[i] = increment;
  barrier();
  for (uint stride = groupSize / 2u; stride > 0u; stride /= 2u)
  {
    if (i < stride)
    {
      groupIncrement[i] += groupIncrement[i + stride];
    }
    barrier();
  }
  if (i == 0u)
  {
    int k = 6 * (bounceIndex - 1);
    addIncrement(k, groupIncrement[0].r);
    addIncrement(k + 2, groupIncrement[0].g);
    addIncrement(k + 4, groupIncrement[0].b);
  }
}
