// Positions from the G-buffer's depth: normalized device coordinates -> grid coordinates.
uniform sampler2D gbufferDepth;
uniform mat4 voxelFromNDC;

vec3 gbufferGridPosition(vec2 uv, float depth)
{
  vec4 p = voxelFromNDC * vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
  return p.xyz / p.w;
}

// The G-buffer pixel a traced pixel (of `traceSize`) stands for, as texture coordinates of its
// centre: the one holding the traced pixel's centre (at half the resolution that centre is a
// corner between four: the one above and right of it), so that the position reconstructed
// there and the depth read there belong together.
vec2 gbufferTracedCoord(vec2 tracedPixel, vec2 traceSize)
{
  vec2 size = vec2(textureSize(gbufferDepth, 0));
  return (floor((tracedPixel + 0.5) / traceSize * size) + 0.5) / size;
}

// The position the G-buffer's depth holds at uv.
vec3 gbufferPositionAt(vec2 uv)
{
  return gbufferGridPosition(uv, textureLod(gbufferDepth, uv, 0.0).r);
}

// The depth surface's own unit normal at p (seen at uv) from the positions of the next pixels
// (`texel` apart), for surfaces VTK drew without a normal; zero where they do not span a plane.
// Its sign is arbitrary.
vec3 gbufferDepthNormal(vec2 uv, vec2 texel, vec3 p)
{
  vec3 n = cross(gbufferPositionAt(uv + vec2(texel.x, 0.0)) - p,
    gbufferPositionAt(uv + vec2(0.0, texel.y)) - p);
  return dot(n, n) > 0.0 ? normalize(n) : vec3(0.0);
}

// The unit normal of the plane p lies in, where the pixels on either side of it (`texel`
// apart) lie in it too, both ways (p inside one triangle, or on a flat surface: not at an
// edge, a crease or a silhouette, nor on a surface a few pixels wide); zero elsewhere. Its
// sign is arbitrary.
vec3 gbufferFacetNormal(vec2 uv, vec2 texel, vec3 p)
{
  vec3 tangents[2];
  for (int axis = 0; axis < 2; ++axis)
  {
    vec2 step = axis == 0 ? vec2(texel.x, 0.0) : vec2(0.0, texel.y);
    vec3 after = gbufferPositionAt(uv + step) - p;
    vec3 before = p - gbufferPositionAt(uv - step);
    // (within about 6 degrees: the depth's rounding, not a fold)
    if (!(dot(after, before) > 0.995 * length(after) * length(before)))
    {
      return vec3(0.0);
    }
    tangents[axis] = after + before;
  }
  vec3 n = cross(tangents[0], tangents[1]);
  return dot(n, n) > 0.0 ? normalize(n) : vec3(0.0);
}
