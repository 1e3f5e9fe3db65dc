// Shows the voxel volumes as the image: each pixel (one invocation, 8x8 tiles) marches its
// camera ray through the grid (Amanatides-Woo traversal) and shows the first occupied voxel's
// albedo, normal, emission or radiance, shaded a little by the voxel face the ray entered
// through so equal colours stay readable.
layout(local_size_x = 8, local_size_y = 8) in;

uniform sampler3D voxelAlbedo;
uniform sampler3D voxelNormal;
uniform sampler3D voxelEmission;
uniform sampler3D voxelRadiance;
uniform int hasEmission;
uniform mat4 voxelFromNDC;   // normalized device coordinates -> voxel coordinates
#include "voxel_grid.glsl"
uniform int debugView;       // 1: albedo, 2: normal, 3: emission, 4: radiance
uniform vec3 backgroundColor;
layout(rgba8, binding = 0) uniform writeonly image2D debugImage;

void main()
{
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(debugImage))))
  {
    return;
  }
  vec2 ndc = (vec2(pixel) + 0.5) / vec2(imageSize(debugImage)) * 2.0 - 1.0;
  vec4 a = voxelFromNDC * vec4(ndc, -1.0, 1.0);
  vec4 b = voxelFromNDC * vec4(ndc, 1.0, 1.0);
  vec3 ro = a.xyz / a.w;
  vec3 rd = b.xyz / b.w - ro;
  // Keep the reciprocal finite for rays parallel to a grid plane.
  vec3 safe = mix(vec3(1e-20), abs(rd), greaterThan(abs(rd), vec3(1e-20)));
  vec3 inv = mix(vec3(-1.0), vec3(1.0), greaterThanEqual(rd, vec3(0.0))) / safe;
  float res = float(voxelResolution);
  vec3 t0 = (vec3(0.0) - ro) * inv;
  vec3 t1 = (vec3(res) - ro) * inv;
  vec3 tn = min(t0, t1);
  vec3 tf = max(t0, t1);
  float tmin = max(max(tn.x, tn.y), max(tn.z, 0.0));
  int face = tn.x >= tn.y && tn.x >= tn.z ? 0 : (tn.y >= tn.z ? 1 : 2);
  const vec3 faceShade = vec3(0.85, 1.0, 0.7);
  float tmax = min(tf.x, min(tf.y, tf.z));
  vec3 color = backgroundColor;
  if (tmin < tmax)
  {
    vec3 p = ro + rd * tmin;
    ivec3 cell = clamp(ivec3(floor(p)), ivec3(0), ivec3(voxelResolution - 1));
    ivec3 stepDir = ivec3(mix(vec3(-1.0), vec3(1.0), greaterThanEqual(rd, vec3(0.0))));
    vec3 tDelta = abs(inv);
    vec3 tNext = (vec3(cell) + max(vec3(stepDir), vec3(0.0)) - ro) * inv;
    for (int s = 0; s < 3 * voxelResolution; ++s)
    {
      if (texelFetch(voxelAlbedo, cell, 0).a > 0.0)
      {
        if (debugView == 1)
        {
          color = texelFetch(voxelAlbedo, cell, 0).rgb;
        }
        else if (debugView == 2)
        {
          color = texelFetch(voxelNormal, cell, 0).rgb;
        }
        else
        {
          vec3 e = debugView == 4 ? texelFetch(voxelRadiance, cell, 0).rgb
                                  : (hasEmission != 0 ? texelFetch(voxelEmission, cell, 0).rgb : vec3(0.0));
          color = e / (1.0 + e);
        }
        color *= faceShade[face];
        break;
      }
      if (tNext.x <= tNext.y && tNext.x <= tNext.z)
      {
        cell.x += stepDir.x;
        tNext.x += tDelta.x;
        face = 0;
      }
      else if (tNext.y <= tNext.z)
      {
        cell.y += stepDir.y;
        tNext.y += tDelta.y;
        face = 1;
      }
      else
      {
        cell.z += stepDir.z;
        tNext.z += tDelta.z;
        face = 2;
      }
      if (any(lessThan(cell, ivec3(0))) || any(greaterThanEqual(cell, ivec3(voxelResolution))))
      {
        break;
      }
    }
  }
  imageStore(debugImage, pixel, vec4(color, 1.0));
}
