// Indirect light in VTK's volume ray caster (VolumeLighting): the light arriving at a ray
// sample from the scene (the last bounce's gather at the volumes' voxels, voxel_bounce.comp),
// which the sample scatters isotropically with its colour. Added to VTK's own colour.
uniform sampler3D voxelgiIncident;
uniform mat4 voxelgiGridFromWorld; // world -> the grid's texture coordinates
uniform float voxelgiIndirectIntensity;

vec3 voxelgiIndirect(vec3 dataPos)
{
  vec4 world = in_volumeMatrix[0] * in_textureDatasetMatrix[0] * vec4(dataPos, 1.0);
  vec3 uvw = (voxelgiGridFromWorld * vec4(world.xyz / world.w, 1.0)).xyz;
  return voxelgiIndirectIntensity * textureLod(voxelgiIncident, uvw, 0.0).rgb;
}
