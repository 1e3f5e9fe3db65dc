// Positions from the G-buffer's depth: normalized device coordinates -> grid coordinates.
uniform sampler2D gbufferDepth;
uniform mat4 voxelFromNDC;

vec3 gbufferGridPosition(vec2 uv, float depth)
{
  vec4 p = voxelFromNDC * vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
  return p.xyz / p.w;
}
