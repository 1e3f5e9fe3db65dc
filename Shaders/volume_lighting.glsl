// Indirect light in VTK's volume ray caster (VolumeLighting): the light arriving at a ray
// sample from the scene (the last bounce's gather at the volumes' voxels, voxel_bounce.comp),
// which the sample scatters isotropically with its colour. Added to VTK's own colour.
uniform sampler3D voxelgiIncident;
uniform mat4 voxelgiGridFromWorld; // world -> the grid's texture coordinates
uniform float voxelgiIndirectIntensity;
// Per ray: its texture coordinates -> the grid's, the grid's voxels per unit of those, and
// the last light read and where.
mat4 voxelgiGridFromData;
float voxelgiVoxels;
vec3 voxelgiReadAt;
vec3 voxelgiRead;

void voxelgiBeginRay()
{
  voxelgiGridFromData = voxelgiGridFromWorld * in_volumeMatrix[0] * in_textureDatasetMatrix[0];
  voxelgiVoxels = float(textureSize(voxelgiIncident, 0).x);
  voxelgiReadAt = vec3(-1e9);
  voxelgiRead = vec3(0.0);
}

vec3 voxelgiIndirect(vec3 dataPos)
{
  vec4 uvw = voxelgiGridFromData * vec4(dataPos, 1.0);
  vec3 at = uvw.xyz / uvw.w;
  // The incident light varies over the grid's voxels, and the ray caster's samples lie a
  // fraction of one apart: read again once the ray has moved half a voxel (the read, one more
  // 3D texture per sample, took a fifth of the ray caster's time).
  if (any(greaterThan(abs(at - voxelgiReadAt) * voxelgiVoxels, vec3(0.5))))
  {
    voxelgiReadAt = at;
    voxelgiRead = textureLod(voxelgiIncident, at, 0.0).rgb;
  }
  return voxelgiIndirectIntensity * voxelgiRead;
}
