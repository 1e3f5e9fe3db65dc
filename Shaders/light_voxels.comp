// Voxel direct lighting: outgoing radiance of every occupied voxel from the renderer's lights
// (VTK's light model, normal-weighted attenuation of the deferred-voxel-shading technique,
// occlusion by soft voxel shadows raymarched toward the light or, with VOXELGI_SHADOW_MAPS,
// by the lights' shadow maps) plus the voxel's emission.
layout(local_size_x = VOXELGI_LOCAL_SIZE, local_size_y = VOXELGI_LOCAL_SIZE, local_size_z = VOXELGI_LOCAL_SIZE) in;

#include "lights.glsl"

uniform sampler3D voxelAlbedo; // rgb albedo, a occupancy; linear filtering softens shadow edges
uniform sampler3D voxelNormal;
uniform sampler3D voxelEmission;
uniform int hasEmission;
uniform int voxelShadows; // raymarched occlusion (for lights without a shadow map)
#ifdef VOXELGI_SHADOW_MAPS
#include "shadow_maps.glsl"
#endif
// Read too with keepIndirect (each invocation its own voxel, read before written).
layout(rgba16f, binding = 0) uniform image3D radianceOut;
layout(rgba16f, binding = 1) uniform image3D directOut;
uniform int writeDirect;
uniform int keepIndirect;


// Transmittance from p toward the light: products of (1 - occupancy) along the ray.
// `grazing`: leave the voxel's own surface layer (conservative voxelization makes it up to
// two voxels thick) also toward grazing lights, whose rays run along it; without, a ray from
// inside a closed object toward a grazing light meets the object's own faces.
float voxelShadow(vec3 p, vec3 side, vec3 toLight, float distance, bool grazing)
{
  float res = float(voxelResolution);
  vec3 origin = p + side * 1.5;
  float transmittance = 1.0;
  float start = grazing ? max(1.0, 1.5 / max(dot(side, toLight), 0.1)) : 1.0;
  for (float t = start; t < min(distance, 2.0 * res) && transmittance > 0.01; t += 1.0)
  {
    vec3 q = origin + toLight * t;
    if (any(lessThan(q, vec3(0.0))) || any(greaterThan(q, vec3(res))))
    {
      break;
    }
    transmittance *= 1.0 - textureLod(voxelAlbedo, q / res, 0.0).a;
  }
  return transmittance;
}

// Normal-weighted attenuation: per dominant voxel face, weighted by the squared components
// of the averaged voxel normal. Zero normals (opposing surfaces in one voxel) use half.
float voxelNormalWeighted(vec3 n, vec3 toLight, bool twoSided)
{
  if (dot(n, n) < 0.25)
  {
    return 0.5;
  }
  vec3 w = n * n;
  vec3 d = twoSided ? abs(toLight) : max(mix(-toLight, toLight, greaterThan(n, vec3(0.0))), 0.0);
  return dot(w, d);
}

void main()
{
  ivec3 v = ivec3(gl_GlobalInvocationID);
  int res = voxelResolution;
  if (any(greaterThanEqual(v, ivec3(res))))
  {
    return;
  }
  vec4 albedo = texelFetch(voxelAlbedo, v, 0);
  vec4 result = vec4(0.0);
  float lit = 1.0;
  if (albedo.a > 0.0)
  {
    vec4 normal = texelFetch(voxelNormal, v, 0);
    vec3 n = normal.xyz * 2.0 - 1.0;
    vec3 p = vec3(v) + 0.5;
    vec3 radiance = hasEmission != 0 ? texelFetch(voxelEmission, v, 0).rgb : vec3(0.0);
    bool twoSided = voxelLightInfo.y != 0;
    // direct light reaching the winding's front (x) and back (y), and the back's unoccluded (z)
    vec3 arriving = vec3(0.0);
    // A volume's voxel (no surface: normal alpha 0, voxel_resolve.comp) scatters none of the
    // lights' direct light: VTK shows a volume unlit, and GI adds to it, and passes on, only
    // the light the scene's surfaces send it.
    int lights = normal.a > 0.0 ? voxelLightInfo.x : 0;
    for (int l = 0; l < lights; ++l)
    {
      vec3 toLight;
      float distance;
      float attenuation = voxelLightIncidence(l, p, toLight, distance);
      float lambert = voxelNormalWeighted(n, toLight, twoSided);
      if (!(attenuation * lambert > 0.0))
      {
        continue;
      }
      bool back = dot(n, n) >= 0.25 && dot(n, toLight) < 0.0;
      vec3 side = dot(n, n) < 0.25 ? toLight : (back ? -n : n);
      vec3 visibility =
        vec3(voxelShadows != 0 ? voxelShadow(p, side, toLight, distance, true) : 1.0);
      vec3 backVisibility = back && voxelShadows != 0
        ? vec3(voxelShadow(p, side, toLight, distance, false))
        : visibility;
#ifdef VOXELGI_SHADOW_MAPS
      if (shadowMapped(l))
      {
        // from just off the voxel's lit side
        visibility = shadowMapVisibility(l, p + side + toLight);
        backVisibility = visibility;
      }
#endif
      vec3 color = voxelLights[l].color.rgb;
      float light = dot(color, vec3(1.0)) * attenuation * lambert;
      radiance += albedo.rgb * color * visibility * (attenuation * lambert);
      // (the light's power that arrives, for the side the bounce gathers over)
      float front = dot(color, visibility) * attenuation * lambert;
      float behind = dot(color, backVisibility) * attenuation * lambert;
      arriving += vec3(float(!back) * front, float(back) * behind, float(back) * light);
    }
    // The direct volume's alpha says which side of the winding the bounce gathers over and
    // the voxel's light leaves toward (negative: the back): VTK lights both sides, and a
    // room seen from inside may be wound outward.
    // The back counts where the lights reach it unoccluded (not through the faces of a
    // closed object, tested without the grazing allowance) and it opens onto space (two
    // voxels free behind it, not the underside of a thin slab lit through the slab).
    bool open = dot(n, n) >= 0.25 &&
      texelFetch(voxelAlbedo, ivec3(floor(p - normalize(n))), 0).a == 0.0 &&
      texelFetch(voxelAlbedo, ivec3(floor(p - 2.0 * normalize(n))), 0).a == 0.0;
    lit = open && arriving.y > arriving.x && arriving.y > 0.9 * arriving.z ? -1.0 : 1.0;
    // Half where no light reaches either side: the side is a guess (the mipmaps then let
    // the voxel's light leave every way, voxel_mipmap.comp).
    lit *= arriving.x + arriving.y > 0.0 ? 1.0 : 0.5;
    // Premultiplied by the occupancy, as the cone tracer composites it: a volume's voxel
    // stops and scatters part of the light (surfaces: all).
    result = vec4(min(radiance, vec3(VOXELGI_HALF_MAX)) * albedo.a, albedo.a);
  }
  vec4 total = result;
  if (keepIndirect != 0 && albedo.a > 0.0)
  {
    vec3 indirect = max(imageLoad(radianceOut, v).rgb - imageLoad(directOut, v).rgb, vec3(0.0));
    total.rgb = min(result.rgb + indirect, vec3(VOXELGI_HALF_MAX));
  }
  imageStore(radianceOut, v, total);
  if (writeDirect != 0)
  {
    imageStore(directOut, v, vec4(result.rgb, albedo.a > 0.0 ? lit : 0.0));
  }
}
