// Per-pixel voxel cone tracing, at the trace resolution (possibly below the image's), one
// invocation per traced pixel in 8x8 tiles (a compute dispatch: on GPUs whose fragment work
// runs on a few of their units, a full-screen fragment pass is many times slower). From
// the G-buffer it reconstructs each pixel's position in grid coordinates, traces diffuse
// cones over the normal's hemisphere (indirect diffuse and AO), one specular cone whose
// aperture follows the specular power, and a narrow cone toward each light for soft shadows
// (with VOXELGI_SHADOW_MAPS, a scene light that has a shadow map is looked up there instead:
// the map holds the geometry itself, where a narrow cone sees the voxels' steps).
// Outputs: 0 = indirect light (diffuse x albedo + specular) and AO, 1 = the part of VTK's
// direct shading (Phong, per shadowed light) that the shadows take away, 2 = the
// surface they belong to (for the next frame's reuse).
// composite.comp upsamples these and composites them with VTK's shading.
//
// Temporal reuse (temporalPhase >= 0, frames where only the camera changed): the tiles of one
// class of four are traced, the others take the previous frame's result where the previous
// frame saw the same surface there (reprojected position, normal and, on specular surfaces,
// the view direction). Where it did not, the pixel is listed, and a second dispatch
// (retracePass) traces the listed pixels side by side: traced in place, one such pixel kept
// its whole group of threads busy for a full trace. Shadows that all come from maps are
// looked up afresh in every pixel.
layout(local_size_x = 8, local_size_y = 8) in;

#include "lights.glsl"
#include "cone_tracing.glsl"
#include "gbuffer_encoding.glsl"
#include "gbuffer_position.glsl"
#ifdef VOXELGI_SHADOW_MAPS
#include "shadow_maps.glsl"
#endif

uniform sampler2D gbufferNormal;   // the packed surface (gbuffer_encoding.glsl)
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
layout(rg32f, binding = 2) uniform writeonly image2D traceSurface; // NDC depth, encoded normal
uniform int temporalPhase;         // tile class traced this frame; -1: every tile
uniform sampler2D previousIndirect;
uniform sampler2D previousShadowed;
uniform sampler2D previousSurface;
uniform mat4 previousGridFromNDC;
uniform mat4 previousNDCFromGrid;
uniform vec4 previousEye;          // grid coordinates (w 1) or direction of view (parallel, w 0)
uniform int retracePass;           // 1: trace the listed pixels, a group's worth to a group
layout(std430, binding = VOXELGI_RETRACE_LIST_BINDING) buffer RetraceList
{
  uint retraceDispatch[4]; // groups x, y, z of the second dispatch; pixels listed
  uint retracePixels[];    // x | y << 16
};

// Half-angle tangent of a cone matching VTK's Phong lobe of this specular power.
float specularTanHalf(float power)
{
  return clamp(tan(sqrt(2.0 / (max(power, 0.0) + 2.0))), 0.02, 1.2);
}

// What VTK's highlight of coefficient 1 reflects of the light around its lobe. VTK's
// Blinn-Phong term ks (n.h)^p is not normalized: its peak is ks whatever the power, so its
// lobe holds about ks 8 / (p + 8) of the incoming energy (the normalized Blinn-Phong lobe
// has the factor (p + 8) / 8). The specular cone carries that share, not ks itself.
float specularReflectance(float power)
{
  return 8.0 / (max(power, 0.0) + 8.0);
}

// The traced pixel's G-buffer sample (nearest), as the full-screen pass read it.
vec4 gbufferAt(sampler2D image, vec2 uv)
{
  return textureLod(image, uv, 0.0);
}

// Frames a result may be carried over before it is traced again: repeated resampling blurs.
// A moving camera carries results across tile classes, whose ages differ: at three, more
// than a third of the pixels aged out in every frame; from seven on, results along a contact
// lingered as bright specks after a headlight orbit (the code holds up to 15).
const uint reuseLimit = 5u;

// A unit vector (octahedral coordinates, 10 bits each) and the result's age in frames, as an
// exact integer in a float.
float encodeSurface(vec3 n, uint age)
{
  uvec2 q = uvec2(round(gbufferOctahedral(n) * 1023.0));
  return float((min(age, reuseLimit) * 1024u + q.x) * 1024u + q.y);
}

vec3 decodeSurface(float code, out uint age)
{
  uint c = uint(code);
  age = c / (1024u * 1024u);
  return gbufferFromOctahedral(vec2(float((c / 1024u) % 1024u), float(c % 1024u)) / 1023.0);
}

// The previous frame's results for the surface at p (normal n, seen along viewDir),
// interpolated bilinearly from its pixels around p's reprojection that held the same
// surface: a point within a tenth of a voxel of p's tangent plane and a quarter voxel of p,
// a normal within ~18 degrees, a result younger than reuseLimit, and a view direction that
// turned less than acos(viewCosine). False when p was out of its view or most of that weight
// belongs to other surfaces; `age` gets the oldest result's age.
bool previousResults(vec3 p, vec3 n, vec3 viewDir, float viewCosine, ivec2 size,
  out vec4 indirect, out vec4 shadowed, out uint age)
{
  vec4 clip = previousNDCFromGrid * vec4(p, 1.0);
  vec3 previousView = previousEye.w > 0.0 ? normalize(p - previousEye.xyz) : previousEye.xyz;
  if (!(clip.w > 0.0) || dot(previousView, viewDir) < viewCosine)
  {
    return false;
  }
  vec2 f = (clip.xy / clip.w * 0.5 + 0.5) * vec2(size) - 0.5;
  vec2 base = floor(f);
  vec2 w = f - base;
  indirect = vec4(0.0);
  shadowed = vec4(0.0);
  age = 0u;
  float weightSum = 0.0;
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < 2; ++i)
    {
      ivec2 texel = ivec2(base) + ivec2(i, j);
      if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, size)))
      {
        continue;
      }
      vec2 surface = texelFetch(previousSurface, texel, 0).xy;
      if (surface.x >= 1.0)
      {
        continue;
      }
      vec4 q = previousGridFromNDC *
        vec4(gbufferTracedCoord(vec2(texel), vec2(size)) * 2.0 - 1.0, surface.x * 2.0 - 1.0, 1.0);
      vec3 d = q.xyz / q.w - p;
      uint texelAge;
      vec3 m = decodeSurface(surface.y, texelAge);
      if (abs(dot(d, n)) > 0.1 || dot(d, d) > 0.0625 || dot(m, n) < 0.95 || texelAge >= reuseLimit)
      {
        continue;
      }
      age = max(age, texelAge);
      float weight = (i == 1 ? w.x : 1.0 - w.x) * (j == 1 ? w.y : 1.0 - w.y);
      indirect += weight * texelFetch(previousIndirect, texel, 0);
      shadowed += weight * texelFetch(previousShadowed, texel, 0);
      weightSum += weight;
    }
  }
  if (weightSum < 0.5)
  {
    return false;
  }
  indirect /= weightSum;
  shadowed /= weightSum;
  return true;
}

// Whether light l's shadow in the pixels is read from its shadow map (else a cone traces it).
bool pixelShadowMap(int l)
{
#ifdef VOXELGI_SHADOW_MAPS
  return shadowMapped(l) && shadowLights[l].z != 0;
#else
  return false;
#endif
}

// Whether every light that casts shadows in the pixels has a shadow map: then the shadows
// are exact and cheap, and a reused tile looks them up afresh instead of resampling the last
// frame's edges.
bool shadowsFromMapsOnly()
{
#ifdef VOXELGI_SHADOW_MAPS
  return shadowInfo.x != 0;
#else
  return false;
#endif
}

// The part of VTK's direct shading (diffuse albedo, specular coefficient and power) at the
// surface point p (normal n, seen along viewDir) that the lights' shadows take away.
vec3 occludedDirect(vec3 p, vec3 origin, vec3 n, vec3 viewDir, vec3 albedo, float specular, float power)
{
  vec3 occluded = vec3(0.0);
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
    vec3 shadow;
#ifdef VOXELGI_SHADOW_MAPS
    if (pixelShadowMap(l))
    {
      shadow = 1.0 - shadowMapSurfaceVisibility(l, p, n, distance);
    }
    else
#endif
    {
      // Toward a grazing light the cone runs along its own surface's voxels: start it where
      // it has risen a voxel and a half above the surface.
      float start = max(1.0, 1.5 / max(dot(n, toLight), 0.1));
      // Stop short of the light by the cone's width there, so that geometry next to the
      // light (the ceiling a lamp hangs from) does not shadow everything it lights.
      float end = min(distance - max(2.0, 2.0 * shadowTanHalf * distance), maxDistance);
      float occlusion;
      voxelConeTrace(origin, toLight, shadowTanHalf, start, end, 0.0, p, n, occlusion);
      shadow = vec3(occlusion);
    }
    float sf = attenuation * pow(max(dot(reflect(-toLight, n), -viewDir), 0.0), power);
    occluded += shadow * (df * albedo + sf * specular) * voxelLights[l].color.rgb;
  }
  return occluded;
}

const uint groupSize = gl_WorkGroupSize.x * gl_WorkGroupSize.y;

// Put the pixel on the list the second dispatch traces, counting its groups.
void listForRetrace(ivec2 pixel)
{
  uint i = atomicAdd(retraceDispatch[3], 1u);
  retracePixels[i] = uint(pixel.x) | (uint(pixel.y) << 16);
  if (i % groupSize == 0u)
  {
    atomicAdd(retraceDispatch[0], 1u);
  }
}

void main()
{
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (retracePass != 0)
  {
    uint i = gl_WorkGroupID.x * groupSize + gl_LocalInvocationIndex;
    if (i >= retraceDispatch[3])
    {
      return;
    }
    pixel = ivec2(retracePixels[i] & 0xffffu, retracePixels[i] >> 16);
  }
  ivec2 size = imageSize(traceIndirect);
  if (any(greaterThanEqual(pixel, size)))
  {
    return;
  }
  vec2 texCoord = gbufferTracedCoord(vec2(pixel), vec2(size));
  // Planes from the G-buffer's next pixels: at a lower trace resolution the next traced ones
  // lie farther apart and more often across an edge.
  vec2 texel = 1.0 / vec2(textureSize(gbufferDepth, 0));
  float depth = gbufferAt(gbufferDepth, texCoord).r;
  if (depth >= 1.0)
  {
    imageStore(traceIndirect, pixel, vec4(0.0, 0.0, 0.0, 1.0));
    imageStore(traceShadowed, pixel, vec4(0.0));
    imageStore(traceSurface, pixel, vec4(1.0, 0.0, 0.0, 0.0));
    return;
  }
  vec3 p = gbufferGridPosition(texCoord, depth);
  vec3 nearP = gbufferGridPosition(texCoord, 0.0);
  vec3 farP = gbufferGridPosition(texCoord, 1.0);
  vec3 viewDir = normalize(farP - nearP);

  float power;
  vec3 n = gbufferSurfaceNormal(gbufferAt(gbufferNormal, texCoord), power);
  if (dot(n, n) < 0.25)
  {
    // VTK computed no normal (unlit actor): take the depth surface's own, from the next
    // traced pixels' positions.
    n = gbufferDepthNormal(texCoord, texel, p);
    n = dot(n, n) > 0.0 ? n : -viewDir;
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

  uvec2 tile = gl_WorkGroupID.xy & 1u;
  if (temporalPhase >= 0 && retracePass == 0 && int(tile.x + 2u * tile.y) != temporalPhase)
  {
    // Specular light depends on the view, and so do the highlights that cone shadows take
    // away (map shadows are looked up afresh below): reuse them only over a small fraction
    // of the lobe.
    bool freshShadows = coneShadows != 0 && shadowsFromMapsOnly();
    bool viewDependent = specular > 0.0 && (specularCone != 0 || (coneShadows != 0 && !freshShadows));
    float viewCosine = viewDependent ? cos(0.2 * atan(specularTanHalf(power))) : -2.0;
    vec4 previousIndirectAO, previousOccluded;
    uint age;
    if (previousResults(p, n, viewDir, viewCosine, size, previousIndirectAO, previousOccluded, age))
    {
      if (freshShadows)
      {
        vec3 occluded = occludedDirect(p, p + n * startOffset, n, viewDir, albedo, specular, power);
        previousOccluded =
          !any(isnan(occluded)) && !any(isinf(occluded)) ? vec4(occluded, 1.0) : vec4(0.0);
      }
      imageStore(traceIndirect, pixel, previousIndirectAO);
      imageStore(traceShadowed, pixel, previousOccluded);
      imageStore(traceSurface, pixel, vec4(depth, encodeSurface(n, age + 1u), 0.0, 0.0));
      return;
    }
    listForRetrace(pixel);
    return;
  }
  imageStore(traceSurface, pixel, vec4(depth, encodeSurface(n, 0u), 0.0, 0.0));

  vec3 origin = p + n * startOffset;

  // The cone set turns by a quarter turn from pixel to pixel of each 2 x 2 block: four
  // neighbours sample four times as many directions, and the composite's tent weighs the
  // four turns alike (a fixed set lights a wall in spots where its cones meet an emitter).
  vec3 t0, b0;
  voxelBasis(n, t0, b0);
  float turn = 1.5707963 * float((pixel.x & 1) + 2 * (pixel.y & 1));
  vec3 t = cos(turn) * t0 + sin(turn) * b0;
  vec3 b = cos(turn) * b0 - sin(turn) * t0;
  // VTK shades with interpolated normals, which on a coarse curved mesh lean up to 30 degrees
  // off its triangles: a cone around such a normal may point below the triangle the pixel
  // lies in, into the surface itself, where no light comes from (it would travel on to
  // whatever lies beyond). Where the pixel's triangle is known from the depth around it.
  vec3 facet = gbufferFacetNormal(texCoord, texel, p);
  facet = dot(facet, viewDir) > 0.0 ? -facet : facet;
  vec3 gathered = vec3(0.0);
  float occlusion = 0.0;
  for (int i = 0; i < coneCount; ++i)
  {
    vec3 d = normalize(coneDirections[i].x * t + coneDirections[i].y * b + coneDirections[i].z * n);
    float coneOcclusion = 1.0;
    if (dot(d, facet) >= 0.0)
    {
      gathered += voxelConeTrace(origin, d, diffuseTanHalf, 1.0, maxDistance, aoFalloff, p, n, coneOcclusion).rgb;
    }
    occlusion += coneOcclusion;
  }
  gathered /= float(max(coneCount, 1));
  float ao = 1.0 - occlusion / float(max(coneCount, 1));
  vec3 indirect = albedo * gathered * indirectIntensity;

  if (specularCone != 0 && specular > 0.0)
  {
    vec3 r = reflect(viewDir, n);
    float ignored;
    indirect += specular * specularIntensity * specularReflectance(power) *
      voxelConeTrace(origin, r, specularTanHalf(power), 1.0, maxDistance, 0.0, p, n, ignored).rgb;
  }

  vec3 shadowed = coneShadows != 0 ? occludedDirect(p, origin, n, viewDir, albedo, specular, power) : vec3(0.0);
  // Never let a non-finite value through.
  bool finite = !any(isnan(indirect)) && !any(isinf(indirect)) && !any(isnan(shadowed)) &&
    !any(isinf(shadowed)) && !isnan(ao);
  imageStore(traceIndirect, pixel, finite ? vec4(indirect, clamp(ao, 0.0, 1.0)) : vec4(0.0, 0.0, 0.0, 1.0));
  imageStore(traceShadowed, pixel, finite ? vec4(shadowed, 1.0) : vec4(0.0));
}
