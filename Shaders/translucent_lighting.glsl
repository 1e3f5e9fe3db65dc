// Indirect light on VTK's translucent surfaces (TranslucentLighting): declarations placed
// after VTK's system declarations in the polydata fragment shader of the translucent actors
// the scan recorded, while VTK's translucent step draws them. They are in the voxels with
// partial occupancy: their cones start above their own voxels (voxelConeFootprint), as the
// trace's do. VTK's colour of the fragment stays; the diffuse colour times the light arriving
// is added to it.
#extension GL_ARB_shading_language_420pack : require
#include "cone_tracing.glsl"

uniform mat4 voxelgiGridFromView;       // VTK's view coordinates -> grid coordinates
uniform mat3 voxelgiGridNormalFromView; // view-space normals -> grid directions (unit scale)
uniform vec3 voxelgiConeDirections[VOXELGI_MAX_CONES]; // tangent space, cosine distributed
uniform int voxelgiConeCount;
uniform float voxelgiConeTanHalf;
uniform float voxelgiMaxDistance;
uniform float voxelgiIndirectIntensity;

// Irradiance / pi at the surface point of view-space position `positionVC` and unit normal
// `normalVC` (VTK's, turned toward the viewer on back faces): equal-weight cones over its
// hemisphere, as the bounce gathers (voxel_bounce.comp).
vec3 voxelgiIndirect(vec3 positionVC, vec3 normalVC)
{
  vec3 p = (voxelgiGridFromView * vec4(positionVC, 1.0)).xyz;
  vec3 n = voxelgiGridNormalFromView * normalVC;
  if (!(dot(n, n) > 0.0))
  {
    return vec3(0.0);
  }
  n = normalize(n);
  vec3 t, b;
  voxelBasis(n, t, b);
  vec3 gathered = vec3(0.0);
  float ignored;
  for (int i = 0; i < voxelgiConeCount; ++i)
  {
    vec3 d = normalize(voxelgiConeDirections[i].x * t + voxelgiConeDirections[i].y * b +
      voxelgiConeDirections[i].z * n);
    gathered += voxelConeTrace(p + n * 0.5, d, voxelgiConeTanHalf, 1.0, voxelgiMaxDistance, 0.0,
      p, n, ignored).rgb;
  }
  return voxelgiIndirectIntensity * gathered / float(max(voxelgiConeCount, 1));
}
