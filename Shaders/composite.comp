//VTK::System::Dec
// Composite at the image's resolution: VTK's shaded colour (the direct term) minus what the
// shadow cones found occluded, darkened by AO, plus the indirect light. The traced buffers
// may be at a lower resolution: each pixel then blends the four nearest traced samples with
// bilinear weights times how well their surfaces match its own (position and normal), so that
// indirect light does not bleed across depth or orientation edges.
in vec2 texCoord;

#include "gbuffer_position.glsl"

uniform sampler2D gbufferColor;
uniform sampler2D gbufferNormal;
uniform sampler2D traceIndirect;   // indirect rgb, AO
uniform sampler2D traceShadowed;   // occluded direct rgb
uniform vec2 traceSize;            // texels of the traced buffers
uniform float aoStrength;
uniform int compositeView;         // 0 composite, 1 direct only, 2 indirect only, 3 AO only

//VTK::Output::Dec

void main()
{
  vec4 color = texture(gbufferColor, texCoord);
  // VTK's shading of very bright lights can overflow the half-float G-buffer: keep it finite.
  color.rgb = clamp(mix(color.rgb, vec3(0.0), isnan(color.rgb)), 0.0, 65504.0);
  float depth = texture(gbufferDepth, texCoord).r;
  if (depth >= 1.0)
  {
    gl_FragData[0] = compositeView == 0 || compositeView == 1 ? color : vec4(compositeView == 3 ? vec3(1.0) : vec3(0.0), color.a);
    gl_FragData[1] = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  vec3 p = gbufferGridPosition(texCoord, depth);
  vec3 n = texture(gbufferNormal, texCoord).xyz;

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
      float d = texture(gbufferDepth, uv).r;
      if (d >= 1.0)
      {
        continue;
      }
      float bilinear = (i == 1 ? w.x : 1.0 - w.x) * (j == 1 ? w.y : 1.0 - w.y);
      // positions within about a voxel, normals facing the same way
      float near = exp(-length(gbufferGridPosition(uv, d) - p));
      vec3 sampleNormal = texture(gbufferNormal, uv).xyz;
      float facing = dot(n, n) > 0.25 && dot(sampleNormal, sampleNormal) > 0.25
        ? pow(max(dot(normalize(n), normalize(sampleNormal)), 0.0), 8.0)
        : 1.0;
      float weight = (bilinear + 1e-3) * near * facing;
      indirectSum += weight * texture(traceIndirect, uv);
      shadowedSum += weight * texture(traceShadowed, uv).rgb;
      weightSum += weight;
    }
  }
  vec4 indirectAO = weightSum > 1e-6 ? indirectSum / weightSum : vec4(0.0, 0.0, 0.0, 1.0);
  vec3 shadowed = weightSum > 1e-6 ? shadowedSum / weightSum : vec3(0.0);

  vec3 direct = max(color.rgb - shadowed, vec3(0.0)) * mix(1.0, indirectAO.a, aoStrength);
  vec3 result = direct + indirectAO.rgb;
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
  result = (any(isnan(result)) || any(isinf(result))) ? vec3(0.0) : min(result, vec3(65504.0));
  gl_FragData[0] = vec4(result, color.a);
  gl_FragData[1] = indirectAO;
}
