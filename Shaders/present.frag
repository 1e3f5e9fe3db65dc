//VTK::System::Dec
// Puts the composite into VTK's image, in one of three modes (presentMode):
// 0: blended into VTK's own image, which VTK has just drawn into its framebuffer with its
// multisampling (present_blend.glsl), where present_samples.comp cannot: dual-source
// blending makes each sample s * scale + add, the depth test GEQUAL against the fragment's
// depth (presentDepth) picks the samples. Pixels the composite leaves as they are are not
// written.
// 1: `presentAdd` as it is over VTK's image (a voxel debug view).
// 2: into a framebuffer of one sample, which VTK has not drawn: VTK's colour as the G-buffer
// holds it (its draw of the same steps at one sample), as 8 bits show it, times scale plus
// add, and the G-buffer's depth for the steps VTK draws next.
// Present compiles it as GLSL 3.30 (the output index).
#include "present_blend.glsl"

uniform sampler2D presentScale; // rgb; a: 1 where the G-buffer has a surface
uniform sampler2D presentAdd;
uniform sampler2D gbufferDepth;
uniform sampler2D gbufferColor;
in vec2 texCoord;
uniform int presentMode;
layout(location = 0, index = 0) out vec4 fragmentAdd;
layout(location = 0, index = 1) out vec4 fragmentScale;
void main()
{
  ivec2 pixel = ivec2(texCoord * vec2(textureSize(presentAdd, 0)));
  vec4 add = texelFetch(presentAdd, pixel, 0);
  if (presentMode == 1)
  {
    fragmentAdd = vec4(add.rgb, 0.0);
    fragmentScale = vec4(0.0, 0.0, 0.0, 1.0);
    gl_FragDepth = 1.0;
    return;
  }
  vec4 scale = texelFetch(presentScale, pixel, 0);
  if (presentMode == 2)
  {
    vec4 color = texelFetch(gbufferColor, pixel, 0);
    fragmentAdd = vec4(clamp(color.rgb, 0.0, 1.0) * scale.rgb + add.rgb, color.a);
    fragmentScale = vec4(0.0);
    gl_FragDepth = texelFetch(gbufferDepth, pixel, 0).r;
    return;
  }
  if (presentLeaves(scale, add))
  {
    discard;
  }
  fragmentAdd = vec4(add.rgb, 0.0);
  fragmentScale = vec4(scale.rgb, 1.0);
  gl_FragDepth = presentDepth(gbufferDepth, pixel, scale);
}
