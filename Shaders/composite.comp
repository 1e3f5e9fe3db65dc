// Composite at the image's resolution, one invocation per pixel in 8x8 tiles: VTK's shaded
// colour minus what the shadow cones found occluded, its ambient term darkened by AO (never
// the lights' direct term or emission), plus the indirect light. Each pixel gathers the traced
// samples around it, weighted by how well their surfaces match its own (position and normal),
// so that indirect light does not bleed across depth or orientation edges: the indirect light
// and AO with a tent two traced pixels wide on each side, which gives the four cone turns of
// a 2 x 2 block (cone_trace.comp) equal weight at any position; the shadows, sharp, with
// bilinear weights over the nearest four (the traced buffers may be at a lower resolution).
layout(local_size_x = 8, local_size_y = 8) in;

#include "gbuffer_position.glsl"

uniform sampler2D gbufferColor;
uniform sampler2D gbufferNormal;
uniform sampler2D gbufferAmbient;  // VTK's ambient term of non-emitters; a: coverage
uniform sampler2D traceIndirect;   // indirect rgb, AO
uniform sampler2D traceShadowed;   // occluded direct rgb
uniform vec2 traceSize;            // texels of the traced buffers
uniform mat3 normalToGrid;         // view-space normals -> grid directions
uniform float aoStrength;
uniform int compositeView;         // 0 composite, 1 direct only, 2 indirect only, 3 AO only
layout(rgba32f, binding = 0) uniform writeonly image2D compositeColor; // linear colour
layout(rgba32f, binding = 1) uniform writeonly image2D compositeIndirect; // indirect rgb, AO
layout(rgba8, binding = 2) uniform writeonly image2D compositeDisplay; // clamped, for Present

void store(ivec2 pixel, vec4 color, vec4 indirect)
{
  imageStore(compositeColor, pixel, color);
  imageStore(compositeIndirect, pixel, indirect);
  imageStore(compositeDisplay, pixel, vec4(clamp(color.rgb, 0.0, 1.0), color.a));
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
    store(pixel, compositeView == 0 || compositeView == 1 ? color : vec4(compositeView == 3 ? vec3(1.0) : vec3(0.0), color.a),
      vec4(0.0, 0.0, 0.0, 1.0));
    return;
  }
  vec3 p = gbufferGridPosition(texCoord, depth);
  vec3 n = texelFetch(gbufferNormal, pixel, 0).xyz;
  bool hasNormal = dot(n, n) > 0.25;
  // The surface's plane: its normal, or where VTK computed none (unlit actors, scenes without
  // lights) the depth surface's own, from the next pixels' positions.
  vec3 gridNormal = hasNormal
    ? normalize(normalToGrid * n)
    : gbufferDepthNormal(texCoord, 1.0 / vec2(imageSize(compositeColor)), p);

  vec2 f = texCoord * traceSize - 0.5;
  vec2 base = floor(f);
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
      vec2 uv = (texel + 0.5) / traceSize;
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
      float near = dot(offset, offset) > 16.0 ? 0.0
        : gridNormal == vec3(0.0) ? exp(-length(offset))
        : 1.0 - smoothstep(0.25, 1.0, abs(dot(offset, gridNormal)));
      vec3 sampleNormal = textureLod(gbufferNormal, uv, 0.0).xyz;
      float facing = hasNormal && dot(sampleNormal, sampleNormal) > 0.25
        ? pow(max(dot(normalize(n), normalize(sampleNormal)), 0.0), 8.0)
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

  vec4 ambientSample = texelFetch(gbufferAmbient, pixel, 0);
  vec3 ambient = ambientSample.a == 1.0 && !any(isnan(ambientSample.rgb))
    ? clamp(ambientSample.rgb, vec3(0.0), color.rgb)
    : vec3(0.0);
  // The share of the pixel that polydata surfaces cover (below 1 on multisampled edges, where
  // VTK's colour is already a blend with what lies behind): the traced terms count that much.
  float coverage = clamp(ambientSample.a, 0.0, 1.0);
  vec3 direct = max(color.rgb - ambient - coverage * shadowed, vec3(0.0)) +
    ambient * mix(1.0, indirectAO.a, aoStrength);
  vec3 result = direct + coverage * indirectAO.rgb;
  if (compositeView == 1)
  {
    result = direct;
  }
  else if (compositeView == 2)
  {
    result = indirectAO.rgb;
  }
  else if (compositeView == 3)
  {
    result = vec3(indirectAO.a);
  }
  // Finite and within the pipeline's half-float range, whatever the lights' intensities.
  result = (any(isnan(result)) || any(isinf(result))) ? vec3(0.0) : min(result, vec3(VOXELGI_HALF_MAX));
  store(pixel, vec4(result, color.a), indirectAO);
}
