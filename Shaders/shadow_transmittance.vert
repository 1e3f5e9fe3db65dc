// Shadow map transmittance of a translucent actor (ShadowTransmittance): its GPU-resident
// triangles (SceneBuffers) drawn from the light as shadow_depth.vert draws opaque casters,
// with the colour the fragment filters the light by.
#include "scene_buffers.glsl"

uniform mat4 shadowClipFromModel;
out vec4 transmitVertexColor;

void main()
{
  gl_Position = shadowClipFromModel * vec4(voxelVertices[gl_VertexID].position, 1.0);
  transmitVertexColor = unpackUnorm4x8(voxelVertices[gl_VertexID].color);
}
