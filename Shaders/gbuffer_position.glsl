// Positions from the G-buffer's depth: normalized device coordinates -> grid coordinates.
uniform sampler2D gbufferDepth;
uniform mat4 voxelFromNDC;

vec3 gbufferGridPosition(vec2 uv, float depth)
{
  vec4 p = voxelFromNDC * vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
  return p.xyz / p.w;
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
