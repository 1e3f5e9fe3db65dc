// An actor's GPU-resident vertices (SceneBuffers), as compute voxelization (voxelize.comp) and
// the shadow maps' depth (shadow_depth.vert) read them.
struct VoxelVertex
{
  vec3 position; // relative to the actor's shift (SceneBuffers), model units
  uint color;    // RGBA8 scalar colour (per-vertex colouring)
};
layout(std430, binding = VOXELGI_SCENE_VERTEX_BINDING) readonly buffer VoxelVertexBuffer
{
  VoxelVertex voxelVertices[];
};
