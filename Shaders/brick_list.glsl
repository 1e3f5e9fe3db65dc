// The occupied bricks of the grid (VOXELGI_LOCAL_SIZE^3 voxels each, one work group of the
// per-voxel stages), listed by the resolve. The stages that only work on occupied voxels
// dispatch one work group per listed brick (glDispatchComputeIndirect on this buffer), so a
// mostly empty grid costs what its surfaces need.
layout(std430, binding = VOXELGI_BRICK_LIST_BINDING) buffer VoxelBrickList
{
  uint brickDispatch[3]; // indirect dispatch arguments: brick count, 1, 1
  uint brickPadding;
  uint bricks[];         // brick coordinates, 10 bits per axis
};

uint voxelBrickPack(uvec3 brick)
{
  return brick.x | (brick.y << 10) | (brick.z << 20);
}

// The voxel of this invocation in a dispatch over the brick list.
ivec3 voxelBrickInvocation()
{
  uint b = bricks[gl_WorkGroupID.x];
  uvec3 brick = uvec3(b & 1023u, (b >> 10) & 1023u, b >> 20);
  return ivec3(brick * uint(VOXELGI_LOCAL_SIZE) + gl_LocalInvocationID);
}
