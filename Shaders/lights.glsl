// The renderer's lights in voxel grid coordinates (one uniform block, filled once per frame;
// light_block.h declares it for the shaders and LightBlock.cxx alike) and VTK's light model
// (as vtkOpenGLPolyDataMapper shades: positional attenuation, spot cone and exponent)
// evaluated in the same space.
#include "voxel_grid.glsl"

#include "light_block.h"

// Unit direction toward light `l` from p (grid coordinates), the distance to it (voxels;
// huge for directional lights) and VTK's attenuation there (spot cone included).
float voxelLightIncidence(int l, vec3 p, out vec3 toLight, out float distance)
{
  VoxelLight light = voxelLights[l];
  if (light.position.w == 0.0)
  {
    toLight = -light.direction.xyz;
    distance = 1e30;
    return 1.0;
  }
  vec3 d = light.position.xyz - p;
  distance = length(d);
  toLight = distance > 0.0 ? d / distance : vec3(0.0, 0.0, 1.0);
  float w = distance * voxelSize;
  float attenuation =
    1.0 / max(light.attenuation.x + light.attenuation.y * w + light.attenuation.z * w * w, 1e-20);
  if (light.direction.w > -1.5)
  {
    float coneDot = dot(-toLight, light.direction.xyz);
    attenuation = coneDot >= light.direction.w ? attenuation * pow(max(coneDot, 0.0), light.color.w) : 0.0;
  }
  return attenuation;
}
