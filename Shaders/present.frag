//VTK::System::Dec
// Puts the composite into VTK's image, in one of three modes (presentMode):
// 0: blended into VTK's own image, which VTK has just drawn into its framebuffer with its
// multisampling: dual-source blending makes each sample s * scale + add (alpha kept), so that
// an edge pixel keeps VTK's coverage. The fragment's depth is the G-buffer surface's, raised
// by the surface's depth change across half a pixel: with the depth test GEQUAL, the samples
// of a pixel that belong to that surface (or lie in front of it) take its light, those of what
// lies behind it at a silhouette keep VTK's colour. Pixels the composite leaves as they are
// (scale 1, add 0) are not written.
// 1: `presentAdd` as it is over VTK's image (a voxel debug view).
// 2: into a framebuffer of one sample, which VTK has not drawn: VTK's colour as the G-buffer
// holds it (its draw of the same steps at one sample), as 8 bits show it, times scale plus
// add, and the G-buffer's depth for the steps VTK draws next.
// Present compiles it as GLSL 3.30 (the output index).
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
  if (all(equal(scale.rgb, vec3(1.0))) && all(equal(add.rgb, vec3(0.0))))
  {
    discard;
  }
  fragmentAdd = vec4(add.rgb, 0.0);
  fragmentScale = vec4(scale.rgb, 1.0);
  float depth = 1.0;
  if (scale.a > 0.5)
  {
    ivec2 last = textureSize(gbufferDepth, 0) - 1;
    depth = texelFetch(gbufferDepth, pixel, 0).r;
    float left = texelFetch(gbufferDepth, max(pixel - ivec2(1, 0), ivec2(0)), 0).r;
    float right = texelFetch(gbufferDepth, min(pixel + ivec2(1, 0), last), 0).r;
    float below = texelFetch(gbufferDepth, max(pixel - ivec2(0, 1), ivec2(0)), 0).r;
    float above = texelFetch(gbufferDepth, min(pixel + ivec2(0, 1), last), 0).r;
    // The surface's own slope: the smaller step on each axis (the larger crosses an edge).
    float slope = min(abs(depth - left), abs(right - depth)) +
      min(abs(depth - below), abs(above - depth));
    depth = min(depth + 0.5 * slope + 1e-6, 1.0);
  }
  gl_FragDepth = depth;
}
