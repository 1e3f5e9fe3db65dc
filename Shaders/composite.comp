// Composite at the image's resolution, one invocation per pixel in 8x8 tiles: VTK's shaded
// colour minus what the shadow cones found occluded, its ambient term darkened by AO (never
// the lights' direct term or emission), plus the indirect light. Besides the linear result,
// it writes what Present blends into each of VTK's own samples, s * scale + add, so that
// VTK's multisampled image keeps its coverage at edges: scale takes VTK's displayed colour to
// the composite's direct part, add is the indirect light (scale 0 where the result replaces
// VTK's colour: the debug views, surfaces without lights). Each pixel gathers the traced
// samples around it, weighted by how well their surfaces match its own (position and normal),
// so that indirect light does not bleed across depth or orientation edges: the indirect light
// and AO with a tent two traced pixels wide on each side, which gives the four cone turns of
// a 2 x 2 block (cone_trace.comp) equal weight at any position; the shadows, sharp, with
// bilinear weights over the nearest four (the traced buffers may be at a lower resolution).
layout(local_size_x = 8, local_size_y = 8) in;

#include "gbuffer_encoding.glsl"
#include "gbuffer_position.glsl"

uniform sampler2D gbufferColor;
uniform sampler2D gbufferNormal;   // the packed surface: normal, specular power, kind
uniform sampler2D gbufferAmbient;  // VTK's ambient term of non-emitters
uniform sampler2D traceIndirect;   // indirect rgb, AO
uniform sampler2D traceShadowed;   // occluded direct rgb
uniform vec2 traceSize;            // texels of the traced buffers
uniform mat3 normalToGrid;         // view-space normals -> grid directions
uniform float aoStrength;
uniform int compositeView;         // 0 composite, 1 direct only, 2 indirect only, 3 AO only
layout(rgba32f, binding = 0) uniform writeonly image2D compositeColor; // linear colour
layout(rgba32f, binding = 1) uniform writeonly image2D compositeIndirect; // indirect rgb, AO
layout(rgba16f, binding = 2) uniform writeonly image2D presentScale; // rgb; a: a surface
layout(rgba16f, binding = 3) uniform writeonly image2D presentAdd;

/// The linear result, and Present's blend: VTK's displayed colour (`shown`, clamped as its
/// 8-bit image holds it) scaled to `kept`, plus `added`.
void store(ivec2 pixel, vec4 color, vec4 indirect, vec3 shown, vec3 kept, vec3 added, bool surface)
{
  imageStore(compositeColor, pixel, color);
  imageStore(compositeIndirect, pixel, indirect);
  shown = clamp(shown, 0.0, 1.0);
  kept = clamp(kept, 0.0, 1.0);
  // Where VTK shows (almost) no light, a ratio means nothing: its samples stay and what is
  // kept beyond them is added (other samples of the pixel may be bright: never zero them).
  bvec3 dark = lessThan(shown, vec3(1.0 / 256.0));
  vec3 scale = mix(min(kept / max(shown, vec3(1.0 / 256.0)), 1.0), vec3(1.0), dark);
  vec3 more = mix(vec3(0.0), max(kept - shown, 0.0), dark);
  imageStore(presentScale, pixel, vec4(scale, surface ? 1.0 : 0.0));
  imageStore(presentAdd, pixel, vec4(clamp(added + more, 0.0, 1.0), 0.0));
}

void main()
{
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(compositeColor))))
  {
    return;
  }
  vec2 texCoord = (vec2(pixel) + 0.5) / vec2(imageSize(compositeColor));
  vec4 color = texelFetch(gbufferColor, pixel, 0);
  // VTK's shading of very bright lights can overflow the half-float G-buffer: keep it finite.
  color.rgb = clamp(mix(color.rgb, vec3(0.0), isnan(color.rgb)), 0.0, VOXELGI_HALF_MAX);
  float depth = texelFetch(gbufferDepth, pixel, 0).r;
  if (depth >= 1.0)
  {
    // VTK's background as it is; the AO and indirect views show white and black there.
    bool view = compositeView >= 2;
    vec3 background = view ? vec3(compositeView == 3 ? 1.0 : 0.0) : color.rgb;
    store(pixel, vec4(background, color.a), vec4(0.0, 0.0, 0.0, 1.0), vec3(1.0),
      vec3(view ? 0.0 : 1.0), view ? background : vec3(0.0), false);
    return;
  }
  vec3 p = gbufferGridPosition(texCoord, depth);
  vec4 surfaceTexel = texelFetch(gbufferNormal, pixel, 0);
  float power;
  vec3 n = gbufferSurfaceNormal(surfaceTexel, power);
  bool hasNormal = dot(n, n) > 0.25;
  // The surface's plane: its normal, or where VTK computed none (unlit actors, scenes without
  // lights) the depth surface's own, from the next pixels' positions.
  vec3 gridNormal = hasNormal
    ? normalize(normalToGrid * n)
    : gbufferDepthNormal(texCoord, 1.0 / vec2(imageSize(compositeColor)), p);

  vec2 f = texCoord * traceSize - 0.5;
  vec2 base = floor(f);
  // "A few voxels" in the image's pixels: at a lower trace resolution the tent's samples lie
  // farther apart, and on a wall seen at a grazing angle a fixed reach kept only the nearest
  // column of them, one cone turn, in stripes.
  float reach = 4.0 * max(float(imageSize(compositeColor).x) / traceSize.x, 1.0);
  vec4 indirectSum = vec4(0.0);
  vec3 shadowedSum = vec3(0.0);
  float indirectWeightSum = 0.0;
  float weightSum = 0.0;
  for (int j = -1; j <= 2; ++j)
  {
    for (int i = -1; i <= 2; ++i)
    {
      vec2 texel = base + vec2(i, j);
      vec2 distance = abs(f - texel);
      float tent = max(2.0 - distance.x, 0.0) * max(2.0 - distance.y, 0.0);
      bool nearest = i >= 0 && i <= 1 && j >= 0 && j <= 1;
      if ((tent <= 0.0 && !nearest) || any(lessThan(texel, vec2(0.0))) ||
        any(greaterThan(texel, traceSize - 1.0)))
      {
        continue;
      }
      vec2 uv = gbufferTracedCoord(texel, traceSize);
      float d = textureLod(gbufferDepth, uv, 0.0).r;
      if (d >= 1.0)
      {
        continue;
      }
      // The same surface: within a quarter voxel of the pixel's tangent plane (the depth
      // buffer's steps stay below that; along the surface the neighbours count alike, so that
      // the cone turns stay balanced), fading out by a voxel, and within a few voxels of the
      // pixel; normals facing the same way.
      vec3 offset = gbufferGridPosition(uv, d) - p;
      float near = dot(offset, offset) > reach * reach ? 0.0
        : gridNormal == vec3(0.0) ? exp(-length(offset))
        : 1.0 - smoothstep(0.25, 1.0, abs(dot(offset, gridNormal)));
      float samplePower;
      vec3 sampleNormal = gbufferSurfaceNormal(textureLod(gbufferNormal, uv, 0.0), samplePower);
      float facing = hasNormal && dot(sampleNormal, sampleNormal) > 0.25
        ? pow(max(dot(n, sampleNormal), 0.0), 8.0)
        : 1.0;
      float match = near * facing;
      indirectSum += (tent + 1e-3) * match * textureLod(traceIndirect, uv, 0.0);
      indirectWeightSum += (tent + 1e-3) * match;
      if (nearest)
      {
        float bilinear = max(1.0 - distance.x, 0.0) * max(1.0 - distance.y, 0.0);
        shadowedSum += (bilinear + 1e-3) * match * textureLod(traceShadowed, uv, 0.0).rgb;
        weightSum += (bilinear + 1e-3) * match;
      }
    }
  }
  vec4 indirectAO =
    indirectWeightSum > 1e-6 ? indirectSum / indirectWeightSum : vec4(0.0, 0.0, 0.0, 1.0);
  vec3 shadowed = weightSum > 1e-6 ? shadowedSum / weightSum : vec3(0.0);

  // What the surface keeps of VTK's colour (gbuffer.frag says how alpha reads), and the part
  // of it AO darkens. Other mappers' pixels (alpha 0) get no traced terms.
  vec3 ambientSample = texelFetch(gbufferAmbient, pixel, 0).rgb;
  ambientSample = any(isnan(ambientSample)) ? vec3(0.0) : max(ambientSample, 0.0);
  float kind = gbufferSurfaceKind(surfaceTexel);
  float coverage = kind > 0.0 ? 1.0 : 0.0;
  vec3 own = kind >= 2.0 ? min(ambientSample, vec3(VOXELGI_HALF_MAX)) : color.rgb;
  vec3 ambient = kind == 1.0 || kind == 2.0 ? min(ambientSample, own) : vec3(0.0);
  vec3 direct = max(own - ambient - coverage * shadowed, vec3(0.0)) +
    ambient * mix(1.0, indirectAO.a, aoStrength);
  vec3 indirect = coverage * indirectAO.rgb;
  bool replaced = kind >= 2.0;
  if (compositeView == 1)
  {
    indirect = vec3(0.0);
  }
  else if (compositeView >= 2)
  {
    direct = compositeView == 2 ? vec3(0.0) : vec3(indirectAO.a);
    indirect = compositeView == 2 ? indirectAO.rgb : vec3(0.0);
    replaced = true;
  }
  // Finite and within the pipeline's half-float range, whatever the lights' intensities.
  bool finite = !any(isnan(direct + indirect)) && !any(isinf(direct + indirect));
  direct = finite ? min(direct, vec3(VOXELGI_HALF_MAX)) : vec3(0.0);
  indirect = finite ? min(indirect, vec3(VOXELGI_HALF_MAX)) : vec3(0.0);
  vec3 result = min(direct + indirect, vec3(VOXELGI_HALF_MAX));
  store(pixel, vec4(result, color.a), indirectAO, replaced ? vec3(1.0) : color.rgb,
    replaced ? vec3(0.0) : direct, replaced ? result : indirect, true);
}
