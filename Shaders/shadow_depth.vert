// Shadow map depth from an actor's GPU-resident triangles (SceneBuffers), without a VTK draw:
// an indexed draw of its triangles' vertex indices whose vertices are pulled from the buffer
// compute voxelization reads (gl_VertexID is the index), drawn once per map layer that sees
// the actor (ShadowMaps).
#include "scene_buffers.glsl"

uniform mat4 shadowClipFromModel;

void main()
{
  gl_Position = shadowClipFromModel * vec4(voxelVertices[gl_VertexID].position, 1.0);
}
