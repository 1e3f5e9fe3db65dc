// Clears the G-buffer's images before VTK's draw stores into them (GBufferPass): the depth to
// the far plane, the colour to the renderer's background, as VTK's clear leaves a pixel no
// surface covers. A dispatch, because glClearTexImage of the two took 0.46 ms at 1080p on an
// H100, whose fragment work runs on a few of its units.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = VOXELGI_GBUFFER_DEPTH_UNIT, r32f) writeonly uniform image2D gbufferDepthImage;
layout(binding = VOXELGI_GBUFFER_COLOR_UNIT, rgba16f) writeonly uniform image2D gbufferColorImage;
uniform vec4 background;

void main()
{
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(gbufferDepthImage))))
  {
    return;
  }
  imageStore(gbufferDepthImage, pixel, vec4(1.0));
  imageStore(gbufferColorImage, pixel, background);
}
