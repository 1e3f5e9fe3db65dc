// The G-buffer's packed surface attachment (RGB10_A2, 4 bytes a pixel: on GPUs with few
// raster units the G-buffer's cost grows with the bytes each pixel writes): the unit
// view-space normal in octahedral coordinates (rg), the specular power on a log scale (b; 0:
// the surface has no normal) and the pixel's kind (a; gbuffer.frag says what each means).
// gbuffer.frag writes it; the trace and the composite read it.

// Octahedral coordinates in [0, 1]^2 of unit vector n, and back.
vec2 gbufferOctahedral(vec3 n)
{
  vec2 e = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
  if (n.z < 0.0)
  {
    e = (1.0 - abs(e.yx)) * mix(vec2(-1.0), vec2(1.0), greaterThanEqual(e, vec2(0.0)));
  }
  return clamp(e * 0.5 + 0.5, 0.0, 1.0);
}

vec3 gbufferFromOctahedral(vec2 o)
{
  vec2 e = o * 2.0 - 1.0;
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0)
  {
    n.xy = (1.0 - abs(n.yx)) * mix(vec2(-1.0), vec2(1.0), greaterThanEqual(n.xy, vec2(0.0)));
  }
  return normalize(n);
}

// (powers up to 2^13: the specular cone stops narrowing near 5000)
const float gbufferPowerOctaves = 13.0;

vec4 gbufferEncodeSurface(vec3 n, float power, float kind)
{
  if (!(dot(n, n) > 0.0))
  {
    return vec4(0.0, 0.0, 0.0, kind / 3.0);
  }
  float level = clamp(log2(max(power, 0.0) + 1.0) / gbufferPowerOctaves, 0.0, 1.0);
  return vec4(gbufferOctahedral(normalize(n)), (1.0 + round(1022.0 * level)) / 1023.0, kind / 3.0);
}

// The unit normal (zero where the surface has none) and specular power of a packed texel.
vec3 gbufferSurfaceNormal(vec4 texel, out float power)
{
  if (texel.b < 0.5 / 1023.0)
  {
    power = 1.0;
    return vec3(0.0);
  }
  power = exp2((texel.b * 1023.0 - 1.0) / 1022.0 * gbufferPowerOctaves) - 1.0;
  return gbufferFromOctahedral(texel.rg);
}

float gbufferSurfaceKind(vec4 texel)
{
  return floor(texel.a * 3.0 + 0.5);
}
