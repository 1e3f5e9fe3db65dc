// The lights' shadow maps (ShadowMaps stage): a depth layer per directional or spot light,
// six (the faces of a cube) per point light, rendered from the light by VTK's mappers, and
// the matrices from grid coordinates to each layer's clip space. Indices are the light
// block's (lights.glsl).
#include "lights.glsl"

uniform sampler2DArrayShadow shadowMaps;
// Per layer, the light translucent casters let through (rgb) and 1 - the nearest one's depth
// (a); read where shadowInfo.y says there are any (ShadowTransmittance).
uniform sampler2DArray shadowTransmittance;

#include "shadow_block.h"

bool shadowMapped(int l)
{
  return shadowLights[l].x >= 0;
}

// The map coordinates (xy) and depth (z) of p (grid coordinates) in light l's layer that
// sees it; false outside every layer's view (nothing there casts a shadow).
bool shadowMapCoordinates(int l, vec3 p, out vec4 coordinates)
{
  int layer = shadowLights[l].x;
  if (shadowLights[l].y == 6)
  {
    vec3 d = p - voxelLights[l].position.xyz;
    vec3 a = abs(d);
    int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    layer += 2 * axis + (d[axis] < 0.0 ? 1 : 0);
  }
  vec4 clip = shadowMatrices[layer] * vec4(p, 1.0);
  vec3 ndc = clip.xyz / clip.w;
  if (!(clip.w > 0.0) || any(greaterThan(abs(ndc), vec3(1.0))))
  {
    return false;
  }
  coordinates = vec4(ndc.xy * 0.5 + 0.5, float(layer), ndc.z * 0.5 + 0.5);
  return true;
}

// The light that translucent casters let through to the point at map coordinates c: theirs
// where it lies behind the nearest of them (beyond a depth step of 2^-14 of the depth range,
// the translucent surface's own depth), else all of it.
vec3 shadowMapTransmittance(vec4 c)
{
  if (shadowInfo.y == 0)
  {
    return vec3(1.0);
  }
  vec4 t = textureLod(shadowTransmittance, c.xyz, 0.0);
  return 1.0 - c.w < t.a - 6e-5 ? t.rgb : vec3(1.0);
}

// Visibility of light l at p: one filtered depth comparison (2 x 2 texels), times what
// translucent casters let through.
vec3 shadowMapVisibility(int l, vec3 p)
{
  vec4 c;
  return shadowMapCoordinates(l, p, c) ? texture(shadowMaps, c) * shadowMapTransmittance(c) : vec3(1.0);
}

// Visibility of light l at a surface point p of normal n (toLight, distance: from
// voxelLightIncidence), filtered over 3 x 3 comparisons a texel apart, each times what
// translucent casters let through there. The point is lifted
// off its surface along n by the filter's reach (2.5 texels): then no tap can fall behind the
// surface's own depth in the map, whatever the angle to the light.
vec3 shadowMapSurfaceVisibility(int l, vec3 p, vec3 n, float distance)
{
  float texel = shadowTexels[l].x + shadowTexels[l].y * min(distance, 1e6);
  vec4 c;
  if (!shadowMapCoordinates(l, p + n * (2.5 * texel), c))
  {
    return vec3(1.0);
  }
  vec2 step = 1.0 / vec2(textureSize(shadowMaps, 0).xy);
  vec3 visibility = vec3(0.0);
  for (int j = -1; j <= 1; ++j)
  {
    for (int i = -1; i <= 1; ++i)
    {
      vec4 tap = c + vec4(vec2(i, j) * step, 0.0, 0.0);
      visibility += texture(shadowMaps, tap) * shadowMapTransmittance(tap);
    }
  }
  return visibility / 9.0;
}
