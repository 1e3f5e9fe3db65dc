// Clears the voxelization accumulators before a revoxelization: everything (clearStatic = 1),
// or only the voxels the flag volume does not mark static, so static geometry is kept while
// dynamic actors are voxelized again. Runs over the bricks the last resolve found occupied
// (outside them every sum is zero already; after allocation the list holds every brick).
layout(local_size_x = VOXELGI_LOCAL_SIZE, local_size_y = VOXELGI_LOCAL_SIZE, local_size_z = VOXELGI_LOCAL_SIZE) in;

#include "voxel_common.glsl"
#include "brick_list.glsl"

layout(r8ui, binding = VOXELGI_FLAG_IMAGE_UNIT) uniform uimage3D voxelFlag;
uniform int clearStatic;

void main()
{
  ivec3 v = voxelBrickInvocation();
  if (any(greaterThanEqual(v, ivec3(voxelResolution))))
  {
    return;
  }
  if (clearStatic == 0 && imageLoad(voxelFlag, v).r != 0u)
  {
    return;
  }
  int i = voxelIndex(v);
  voxelCount[i] = 0u;
  voxelAlbedoR[i] = 0u;
  voxelAlbedoG[i] = 0u;
  voxelAlbedoB[i] = 0u;
  voxelNormalX[i] = 0u;
  voxelNormalY[i] = 0u;
  voxelNormalZ[i] = 0u;
#ifdef VOXELGI_EMISSION
  voxelEmissionR[i] = 0u;
  voxelEmissionG[i] = 0u;
  voxelEmissionB[i] = 0u;
  voxelEmissionCoverage[i] = 0u;
#endif
#ifdef VOXELGI_TRANSLUCENT
  voxelClearness[i] = 0u;
#endif
  if (clearStatic != 0)
  {
    imageStore(voxelFlag, v, uvec4(0u));
  }
}
