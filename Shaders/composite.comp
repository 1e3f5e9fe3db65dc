// Composite at the image's resolution, one invocation per pixel in 8x8 tiles: VTK's shaded
// colour minus what the shadow cones found occluded, its ambient term darkened by AO (never
// the lights' direct term or emission), plus the indirect light. The traced buffers
// may be at a lower resolution: each pixel then blends the four nearest traced samples with
// bilinear weights times how well their surfaces match its own (position and normal), so that
// indirect light does not bleed across depth or orientation edges.
layout(local_size_x = 8, local_size_y = 8) in;

#include "gbuffer_position.glsl"

uniform sampler2D gbufferColor;
uniform sampler2D gbufferNormal;
uniform sampler2D gbufferAmbient;  // VTK's ambient term of non-emitters; a: coverage
uniform sampler2D traceIndirect;   // indirect rgb, AO
uniform sampler2D traceShadowed;   // occluded direct rgb
uniform vec2 traceSize;            // texels of the traced buffers
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

  vec2 f = texCoord * traceSize - 0.5;
  vec2 base = floor(f);
  vec2 w = f - base;
  vec4 indirectSum = vec4(0.0);
  vec3 shadowedSum = vec3(0.0);
  float weightSum = 0.0;
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < 2; ++i)
    {
      vec2 uv = (clamp(base + vec2(i, j), vec2(0.0), traceSize - 1.0) + 0.5) / traceSize;
      float d = textureLod(gbufferDepth, uv, 0.0).r;
      if (d >= 1.0)
      {
        continue;
      }
      float bilinear = (i == 1 ? w.x : 1.0 - w.x) * (j == 1 ? w.y : 1.0 - w.y);
      // positions within about a voxel, normals facing the same way
      float near = exp(-length(gbufferGridPosition(uv, d) - p));
      vec3 sampleNormal = textureLod(gbufferNormal, uv, 0.0).xyz;
      float facing = dot(n, n) > 0.25 && dot(sampleNormal, sampleNormal) > 0.25
        ? pow(max(dot(normalize(n), normalize(sampleNormal)), 0.0), 8.0)
        : 1.0;
      float weight = (bilinear + 1e-3) * near * facing;
      indirectSum += weight * textureLod(traceIndirect, uv, 0.0);
      shadowedSum += weight * textureLod(traceShadowed, uv, 0.0).rgb;
      weightSum += weight;
    }
  }
  vec4 indirectAO = weightSum > 1e-6 ? indirectSum / weightSum : vec4(0.0, 0.0, 0.0, 1.0);
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
