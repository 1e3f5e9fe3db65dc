// Per-pixel voxel cone tracing, at the trace resolution (possibly below the image's), one
// invocation per traced pixel in 8x8 tiles (a compute dispatch: on GPUs whose fragment work
// runs on a few of their units, a full-screen fragment pass is many times slower). From
// the G-buffer it reconstructs each pixel's position in grid coordinates, traces diffuse
// cones over the normal's hemisphere (indirect diffuse and AO), one specular cone whose
// aperture follows the specular power, and a narrow cone toward each light for soft shadows.
// Outputs: 0 = indirect light (diffuse x albedo + specular) and AO, 1 = the part of VTK's
// direct shading (Phong, per shadowed light) that the shadow cones find occluded.
// composite.comp upsamples these and composites them with VTK's shading.
layout(local_size_x = 8, local_size_y = 8) in;

#include "lights.glsl"
#include "cone_tracing.glsl"
#include "gbuffer_position.glsl"

uniform sampler2D gbufferNormal;
uniform sampler2D gbufferMaterial;
uniform mat3 normalToGrid;      // view-space normals -> grid directions
uniform vec3 coneDirections[VOXELGI_MAX_CONES];
uniform int coneCount;
uniform float diffuseTanHalf;
uniform float maxDistance;      // voxels
uniform float startOffset;      // voxels along the normal, against self-illumination
uniform float indirectIntensity;
uniform float specularIntensity;
uniform int specularCone;
uniform float aoFalloff;
uniform int coneShadows;
uniform float shadowTanHalf;
layout(rgba16f, binding = 0) uniform writeonly image2D traceIndirect; // indirect rgb, AO
layout(rgba16f, binding = 1) uniform writeonly image2D traceShadowed; // occluded direct rgb

// Half-angle tangent of a cone matching VTK's Phong lobe of this specular power.
float specularTanHalf(float power)
{
  return clamp(tan(sqrt(2.0 / (max(power, 0.0) + 2.0))), 0.02, 1.2);
}

// The traced pixel's G-buffer sample (nearest), as the full-screen pass read it.
vec4 gbufferAt(sampler2D image, vec2 uv)
{
  return textureLod(image, uv, 0.0);
}

void main()
{
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(traceIndirect);
  if (any(greaterThanEqual(pixel, size)))
  {
    return;
  }
  vec2 texel = 1.0 / vec2(size);
  vec2 texCoord = (vec2(pixel) + 0.5) * texel;
  float depth = gbufferAt(gbufferDepth, texCoord).r;
  if (depth >= 1.0)
  {
    imageStore(traceIndirect, pixel, vec4(0.0, 0.0, 0.0, 1.0));
    imageStore(traceShadowed, pixel, vec4(0.0));
    return;
  }
  vec3 p = gbufferGridPosition(texCoord, depth);
  vec3 nearP = gbufferGridPosition(texCoord, 0.0);
  vec3 farP = gbufferGridPosition(texCoord, 1.0);
  vec3 viewDir = normalize(farP - nearP);

  vec4 normalSpec = gbufferAt(gbufferNormal, texCoord);
  vec3 n = normalSpec.xyz;
  if (dot(n, n) < 0.25)
  {
    // VTK computed no normal (unlit actor): take the depth surface's own, from the next
    // traced pixels' positions.
    vec2 dx = texCoord + vec2(texel.x, 0.0);
    vec2 dy = texCoord + vec2(0.0, texel.y);
    n = cross(gbufferGridPosition(dx, gbufferAt(gbufferDepth, dx).r) - p,
      gbufferGridPosition(dy, gbufferAt(gbufferDepth, dy).r) - p);
    n = dot(n, n) > 0.0 ? normalize(n) : -viewDir;
  }
  else
  {
    n = normalize(normalToGrid * n);
  }
  if (dot(n, viewDir) > 0.0)
  {
    n = -n;
  }
  vec4 material = gbufferAt(gbufferMaterial, texCoord);
  vec3 albedo = material.rgb;
  float specular = material.a;
  vec3 origin = p + n * startOffset;

  vec3 t, b;
  voxelBasis(n, t, b);
  vec3 gathered = vec3(0.0);
  float occlusion = 0.0;
  for (int i = 0; i < coneCount; ++i)
  {
    vec3 d = normalize(coneDirections[i].x * t + coneDirections[i].y * b + coneDirections[i].z * n);
    float coneOcclusion;
    gathered += voxelConeTrace(origin, d, diffuseTanHalf, 1.0, maxDistance, aoFalloff, p, n, coneOcclusion).rgb;
    occlusion += coneOcclusion;
  }
  gathered /= float(max(coneCount, 1));
  float ao = 1.0 - occlusion / float(max(coneCount, 1));
  vec3 indirect = albedo * gathered * indirectIntensity;

  if (specularCone != 0 && specular > 0.0)
  {
    vec3 r = reflect(viewDir, n);
    float ignored;
    indirect += specular * specularIntensity *
      voxelConeTrace(origin, r, specularTanHalf(normalSpec.w), 1.0, maxDistance, 0.0, p, n, ignored).rgb;
  }

  vec3 shadowed = vec3(0.0);
  if (coneShadows != 0)
  {
    for (int l = 0; l < voxelLightInfo.x; ++l)
    {
      if (voxelLights[l].attenuation.w != 0.0)
      {
        continue; // a headlight's shadows are hidden behind what casts them
      }
      vec3 toLight;
      float distance;
      float attenuation = voxelLightIncidence(l, p, toLight, distance);
      float df = attenuation * dot(n, toLight);
      if (!(df > 0.0))
      {
        continue;
      }
      // Toward a grazing light the cone runs along its own surface's voxels: start it where
      // it has risen a voxel and a half above the surface.
      float start = max(1.0, 1.5 / max(dot(n, toLight), 0.1));
      // Stop short of the light by the cone's width there, so that geometry next to the light
      // (the ceiling a lamp hangs from) does not shadow everything it lights.
      float end = min(distance - max(2.0, 2.0 * shadowTanHalf * distance), maxDistance);
      float shadow;
      voxelConeTrace(origin, toLight, shadowTanHalf, start, end, 0.0, p, n, shadow);
      float sf = attenuation * pow(max(dot(reflect(-toLight, n), -viewDir), 0.0), normalSpec.w);
      shadowed += shadow * (df * albedo + sf * specular) * voxelLights[l].color.rgb;
    }
  }
  // Never let a non-finite value through.
  bool finite = !any(isnan(indirect)) && !any(isinf(indirect)) && !any(isnan(shadowed)) &&
    !any(isinf(shadowed)) && !isnan(ao);
  imageStore(traceIndirect, pixel, finite ? vec4(indirect, clamp(ao, 0.0, 1.0)) : vec4(0.0, 0.0, 0.0, 1.0));
  imageStore(traceShadowed, pixel, finite ? vec4(shadowed, 1.0) : vec4(0.0));
}
