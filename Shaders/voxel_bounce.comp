// One bounce of indirect diffuse light per occupied voxel (over the occupied bricks): cones
// over the lit side's hemisphere (light_voxels.comp; six axis cones where normals cancel)
// gather the previous radiance from the mipmaps; radiance = direct + albedo x gathered. Cone
// weights sum to one, albedo is below one: repeated bounces converge from below (energy bounded).
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
layout(rgba16f, binding = 0) uniform writeonly image3D radianceOut;
#ifdef VOXELGI_VOLUMES
// The light arriving at voxels without a normal (a volume's: isotropic), which VTK's volume
// shading adds (VolumeLighting); zero elsewhere in the occupied bricks.
layout(r11f_g11f_b10f, binding = 1) uniform writeonly image3D incidentOut;
#endif


void main()
{
  ivec3 v = voxelBrickInvocation(); // occupied bricks only
  int res = voxelResolution;
  if (any(greaterThanEqual(v, ivec3(res))))
  {
    return;
  }
  vec4 albedo = texelFetch(voxelAlbedo, v, 0);
#ifdef VOXELGI_VOLUMES
  imageStore(incidentOut, v, vec4(0.0));
#endif
  if (albedo.a == 0.0)
  {
    return;
  }
  vec4 direct = texelFetch(voxelDirect, v, 0);
  vec3 n = texelFetch(voxelNormal, v, 0).xyz * 2.0 - 1.0;
  vec3 p = vec3(v) + 0.5;
  vec3 gathered = vec3(0.0);
  float ignored;
  if (dot(n, n) < 0.25)
  {
    const vec3 axes[6] = vec3[6](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0),
      vec3(0, 0, 1), vec3(0, 0, -1));
    for (int i = 0; i < 6; ++i)
    {
      gathered += voxelConeTrace(p + axes[i], axes[i], coneTanHalf, 1.0, maxDistance, 0.0, p, vec3(0.0), ignored).rgb;
    }
    gathered /= 6.0;
#ifdef VOXELGI_VOLUMES
    imageStore(incidentOut, v, vec4(gathered, 0.0));
#endif
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
  vec3 scattered = albedo.a * albedo.rgb * gathered;
  imageStore(radianceOut, v, vec4(min(direct.rgb + scattered, vec3(VOXELGI_HALF_MAX)), albedo.a));
}
