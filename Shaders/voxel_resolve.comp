// Turns the accumulated sums into the voxel volumes the later stages sample: mean albedo
// (alpha: the share of light the voxel stops, 1 where only opaque surfaces are; less where
// translucent ones are, voxel_common.glsl), mean unit normal (zero where the normals cancel
// out) and the emission of the voxel's covered fraction; and lists the occupied bricks
// (brick_list.glsl). With VOXELGI_VOLUMES, a voxel no surface reached takes the volumes'
// colour and partial occupancy (voxelize_volume.comp), no normal.
layout(local_size_x = VOXELGI_LOCAL_SIZE, local_size_y = VOXELGI_LOCAL_SIZE, local_size_z = VOXELGI_LOCAL_SIZE) in;

#include "voxel_common.glsl"
#include "brick_list.glsl"

layout(rgba8, binding = 1) uniform writeonly image3D voxelAlbedo;
layout(rgba8, binding = 2) uniform writeonly image3D voxelNormal;
#ifdef VOXELGI_EMISSION
layout(rgba16f, binding = 3) uniform writeonly image3D voxelEmission;
#endif
#ifdef VOXELGI_VOLUMES
layout(rgba8, binding = 4) uniform readonly image3D volumeVoxels;
#endif


shared uint brickOccupied;

void main()
{
  // Resolutions are powers of two of at least 16: every invocation is inside the grid, and
  // all of them reach the barriers.
  ivec3 v = ivec3(gl_GlobalInvocationID);
  if (gl_LocalInvocationIndex == 0u)
  {
    brickOccupied = 0u;
  }
  barrier();
  int i = voxelIndex(v);
  uint count = voxelCount[i];
  vec4 albedo = vec4(0.0);
  vec4 normal = vec4(0.5, 0.5, 0.5, 0.0);
  vec3 emission = vec3(0.0);
  if (count > 0u)
  {
    brickOccupied = 1u;
    float n = float(count);
    albedo = vec4(voxelMean(voxelAlbedoR[i], voxelAlbedoG[i], voxelAlbedoB[i], n), 1.0);
#ifdef VOXELGI_TRANSLUCENT
    albedo.a = 1.0 - float(voxelClearness[i]) / (255.0 * n);
#endif
    vec3 m = voxelMean(voxelNormalX[i], voxelNormalY[i], voxelNormalZ[i], n) * 2.0 - 1.0;
    float len = length(m);
    normal = vec4((len > 1e-3 ? m / len : vec3(0.0)) * 0.5 + 0.5, 1.0);
#ifdef VOXELGI_EMISSION
    vec3 brightest = vec3(uintBitsToFloat(voxelEmissionR[i]), uintBitsToFloat(voxelEmissionG[i]),
      uintBitsToFloat(voxelEmissionB[i]));
    emission = brightest * min(float(voxelEmissionCoverage[i]) / voxelCoverageScale, 1.0);
#endif
  }
#ifdef VOXELGI_VOLUMES
  else
  {
    vec4 volume = imageLoad(volumeVoxels, v);
    if (volume.a > 0.0)
    {
      brickOccupied = 1u;
      albedo = volume;
    }
  }
#endif
  imageStore(voxelAlbedo, v, albedo);
  imageStore(voxelNormal, v, normal);
#ifdef VOXELGI_EMISSION
  imageStore(voxelEmission, v, vec4(emission, 1.0));
#endif
  barrier();
  if (gl_LocalInvocationIndex == 0u && brickOccupied != 0u)
  {
    bricks[atomicAdd(brickDispatch[0], 1u)] = voxelBrickPack(gl_WorkGroupID);
  }
}
