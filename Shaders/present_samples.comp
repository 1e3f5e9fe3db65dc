// Present's blend (present_blend.glsl) as a dispatch, one invocation per pixel of the
// renderer's viewport in 8x8 tiles: each of VTK's samples that VTK's own depth puts on or in
// front of the G-buffer's surface is read from VTK's colour texture and written back as
// s * scale + add. The same blend as present.frag's, without the raster pipeline.
// VOXELGI_MULTISAMPLE: VTK's framebuffer is multisampled; VOXELGI_COLOR_FORMAT: its colour
// texture's format as an image format qualifier.
layout(local_size_x = 8, local_size_y = 8) in;

#include "present_blend.glsl"

#ifdef VOXELGI_MULTISAMPLE
uniform sampler2DMS framebufferDepth;
layout(VOXELGI_COLOR_FORMAT, binding = 0) uniform image2DMS framebufferColor;
#define VOXELGI_SAMPLE(s) , s
#else
uniform sampler2D framebufferDepth; // its level 0 is read as the one sample
layout(VOXELGI_COLOR_FORMAT, binding = 0) uniform image2D framebufferColor;
#define VOXELGI_SAMPLE(s)
#endif

uniform sampler2D presentScale; // rgb; a: 1 where the G-buffer has a surface
uniform sampler2D presentAdd;
uniform sampler2D gbufferDepth;
uniform ivec2 viewportOrigin; // the viewport's corner in VTK's framebuffer
uniform int samples;

void main()
{
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, textureSize(presentAdd, 0))))
  {
    return;
  }
  vec4 scale = texelFetch(presentScale, pixel, 0);
  vec4 add = texelFetch(presentAdd, pixel, 0);
  if (presentLeaves(scale, add))
  {
    return;
  }
  float limit = presentDepth(gbufferDepth, pixel, scale);
  ivec2 target = pixel + viewportOrigin;
  for (int s = 0; s < samples; ++s)
  {
    if (texelFetch(framebufferDepth, target, s).r <= limit)
    {
      vec4 color = imageLoad(framebufferColor, target VOXELGI_SAMPLE(s));
      imageStore(framebufferColor, target VOXELGI_SAMPLE(s),
        vec4(color.rgb * scale.rgb + add.rgb, color.a));
    }
  }
}
