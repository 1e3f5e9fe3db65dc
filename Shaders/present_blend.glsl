// Present's blend of the composite into VTK's image (present.frag, present_samples.comp):
// each of a pixel's samples that belongs to the G-buffer's surface (or lies in front of it)
// becomes s * scale + add (alpha kept); those of what lies behind it at a silhouette keep
// VTK's colour, so that an edge pixel keeps VTK's coverage.

/// Whether the composite leaves the pixel as VTK drew it (scale 1, add 0).
bool presentLeaves(vec4 scale, vec4 add)
{
  return all(equal(scale.rgb, vec3(1.0))) && all(equal(add.rgb, vec3(0.0)));
}

/// The depth up to which the pixel's samples take the composite: the G-buffer surface's,
/// raised by the surface's depth change across half a pixel (a sample of the same surface
/// lies within it); 1 where the pixel has no surface (scale's alpha 0).
float presentDepth(sampler2D gbufferDepth, ivec2 pixel, vec4 scale)
{
  if (scale.a <= 0.5)
  {
    return 1.0;
  }
  ivec2 last = textureSize(gbufferDepth, 0) - 1;
  float depth = texelFetch(gbufferDepth, pixel, 0).r;
  float left = texelFetch(gbufferDepth, max(pixel - ivec2(1, 0), ivec2(0)), 0).r;
  float right = texelFetch(gbufferDepth, min(pixel + ivec2(1, 0), last), 0).r;
  float below = texelFetch(gbufferDepth, max(pixel - ivec2(0, 1), ivec2(0)), 0).r;
  float above = texelFetch(gbufferDepth, min(pixel + ivec2(0, 1), last), 0).r;
  // The surface's own slope: the smaller step on each axis (the larger crosses an edge).
  float slope = min(abs(depth - left), abs(right - depth)) +
    min(abs(depth - below), abs(above - depth));
  return min(depth + 0.5 * slope + 1e-6, 1.0);
}
