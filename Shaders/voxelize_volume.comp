// Volume resampling (VolumeVoxels): a vtkVolume's scalars through its transfer functions into
// the grid's volume of partial occupancy (rgb colour, a the share of light a voxel stops).
// VTK's scalar opacity is per ScalarOpacityUnitDistance: over a voxel of edge h it stops
// 1 - (1 - alpha)^(h / unit) = 1 - exp(-sigma h / unit), sigma = -ln(1 - alpha). Eight samples
// a voxel average sigma (the mean transmittance of a volume finer than the grid); overlapping
// volumes add their sigma, and colours mix by it.
layout(local_size_x = VOXELGI_LOCAL_SIZE, local_size_y = VOXELGI_LOCAL_SIZE, local_size_z = VOXELGI_LOCAL_SIZE) in;

#include "voxel_grid.glsl"

uniform sampler3D volumeScalars;   // one float a point, linear filtering
uniform sampler2D volumeTransfer;  // rgb colour, a opacity per unit distance, over volumeRange
uniform mat4 volumeIndexFromGrid;  // grid coordinates -> continuous point index (point i at i)
uniform vec3 volumeDimensions;     // points per axis
uniform vec2 volumeRange;          // the scalars at the table's first and last entry
uniform float volumeUnitVoxels;    // ScalarOpacityUnitDistance in voxels
uniform vec3 volumeFirst;          // the first voxel of the dispatch
uniform int volumeOverwrite;       // 1: the first volume, which writes every voxel
layout(rgba8, binding = 0) uniform image3D volumeGrid;

const float volumeTableSize = 256.0;

void main()
{
  ivec3 v = ivec3(volumeFirst) + ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(v, ivec3(voxelResolution))))
  {
    return;
  }
  float sigma = 0.0;
  vec3 color = vec3(0.0);
  for (int s = 0; s < 8; ++s)
  {
    vec3 q = vec3(v) + 0.25 + 0.5 * vec3(s & 1, (s >> 1) & 1, (s >> 2) & 1);
    vec3 index = (volumeIndexFromGrid * vec4(q, 1.0)).xyz;
    if (any(lessThan(index, vec3(0.0))) || any(greaterThan(index, volumeDimensions - 1.0)))
    {
      continue; // outside the volume's points: nothing there
    }
    float scalar = textureLod(volumeScalars, (index + 0.5) / volumeDimensions, 0.0).r;
    if (isnan(scalar) || isinf(scalar))
    {
      continue;
    }
    float span = volumeRange.y - volumeRange.x;
    float u = span > 0.0 ? clamp((scalar - volumeRange.x) / span, 0.0, 1.0) : 0.0;
    vec4 entry = textureLod(volumeTransfer,
      vec2((u * (volumeTableSize - 1.0) + 0.5) / volumeTableSize, 0.5), 0.0);
    float extinction = -log(max(1.0 - entry.a, 1e-6));
    sigma += extinction;
    color += extinction * entry.rgb;
  }
  // Extinction over one voxel, in the units of the occupancy's exponent.
  float added = sigma / (8.0 * volumeUnitVoxels);
  vec4 old = volumeOverwrite != 0 ? vec4(0.0) : imageLoad(volumeGrid, v);
  if (added <= 0.0)
  {
    if (volumeOverwrite != 0)
    {
      imageStore(volumeGrid, v, vec4(0.0));
    }
    return;
  }
  float had = -log(max(1.0 - old.a, 1e-6));
  float total = had + added;
  vec3 mixed = (old.rgb * had + (color / sigma) * added) / total;
  imageStore(volumeGrid, v, vec4(mixed, 1.0 - exp(-total)));
}
