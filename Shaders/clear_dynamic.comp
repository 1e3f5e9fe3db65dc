// Clears the voxelization accumulators before a revoxelization: everything (clearStatic = 1),
// or only the voxels the flag volume does not mark static, so static geometry is kept while
// dynamic actors are voxelized again.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "voxel_common.glsl"

layout(r8ui, binding = 0) uniform uimage3D voxelFlag;
uniform int clearStatic;

void main()
{
  ivec3 v = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(v, ivec3(voxelResolution))))
  {
    return;
  }
  if (clearStatic == 0 && imageLoad(voxelFlag, v).r != 0u)
  {
    return;
  }
  int i = voxelIndex(v);
  voxelAccum[VOXEL_COUNT].value[i] = 0u;
  voxelAccum[VOXEL_ALBEDO].value[i] = 0u;
  voxelAccum[VOXEL_ALBEDO + 1].value[i] = 0u;
  voxelAccum[VOXEL_ALBEDO + 2].value[i] = 0u;
  voxelAccum[VOXEL_NORMAL].value[i] = 0u;
  voxelAccum[VOXEL_NORMAL + 1].value[i] = 0u;
  voxelAccum[VOXEL_NORMAL + 2].value[i] = 0u;
#if VOXEL_CHANNELS > 7
  voxelAccum[VOXEL_EMISSION].value[i] = 0u;
  voxelAccum[VOXEL_EMISSION + 1].value[i] = 0u;
  voxelAccum[VOXEL_EMISSION + 2].value[i] = 0u;
#endif
  if (clearStatic != 0)
  {
    imageStore(voxelFlag, v, uvec4(0u));
  }
}
