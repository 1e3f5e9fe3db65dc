// Shadow map depth from an actor's GPU-resident triangles (SceneBuffers), without a VTK draw:
// a vertex per triangle corner, pulled from the buffers compute voxelization reads, drawn
// once per map layer that sees the actor (ShadowMaps).
#include "scene_buffers.glsl"

uniform mat4 shadowClipFromModel;

void main()
{
  uint index = voxelTriangles[gl_VertexID / 3][gl_VertexID % 3];
  gl_Position = shadowClipFromModel * vec4(voxelVertices[index].position, 1.0);
}
