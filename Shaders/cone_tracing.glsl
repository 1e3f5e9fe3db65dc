// Voxel cone tracing over the radiance volume and its anisotropic mipmaps (six directional
// volumes at half resolution, one per axis direction a cone can travel), shared by the
// per-pixel trace and the per-voxel bounce.
#include "voxel_grid.glsl"

uniform sampler3D voxelRadiance; // rgb radiance premultiplied by a (occupancy); mips if isotropic
uniform sampler3D voxelPosX;
uniform sampler3D voxelNegX;
uniform sampler3D voxelPosY;
uniform sampler3D voxelNegY;
uniform sampler3D voxelPosZ;
uniform sampler3D voxelNegZ;
uniform int voxelIsotropic;
uniform float voxelMinLevel;  // 1 when the radiance volume itself must not be sampled
uniform float coneStepFactor; // step length as a fraction of the cone diameter

// Sample for a cone of `diameter` voxels travelling along `dir` at p (grid coordinates).
vec4 voxelSampleCone(vec3 p, float diameter, vec3 dir)
{
  vec3 uvw = p / float(voxelResolution);
  float level = max(log2(max(diameter, 1.0)), voxelMinLevel);
  if (voxelIsotropic != 0)
  {
    return textureLod(voxelRadiance, uvw, level);
  }
  float lod = max(level - 1.0, 0.0);
  vec3 w = dir * dir;
  vec4 aniso = w.x * (dir.x >= 0.0 ? textureLod(voxelPosX, uvw, lod) : textureLod(voxelNegX, uvw, lod)) +
    w.y * (dir.y >= 0.0 ? textureLod(voxelPosY, uvw, lod) : textureLod(voxelNegY, uvw, lod)) +
    w.z * (dir.z >= 0.0 ? textureLod(voxelPosZ, uvw, lod) : textureLod(voxelNegZ, uvw, lod));
  if (level >= 1.0)
  {
    return aniso;
  }
  // Between one and two voxels: blend the full-resolution volume into the first mip.
  return mix(textureLod(voxelRadiance, uvw, 0.0), aniso, level);
}

// Whether the voxel holding grid point q is occupied (the radiance volume's alpha: its
// occupancy, which no stage changes after the lighting).
bool voxelOccupied(vec3 q)
{
  ivec3 v = clamp(ivec3(floor(q)), ivec3(0), ivec3(voxelResolution - 1));
  return texelFetch(voxelRadiance, v, 0).a >= 0.5;
}

// The texel diameter (at least 2) a cone of `diameter` voxels reads at the scene's bounds.
float voxelSceneFaceLevel(float diameter)
{
  return exp2(max(floor(log2(diameter)), 1.0));
}

// Whether the scene's face across `axis`, left at p by a cone from `origin` along `dir` that
// reads texels of diameter d there, does not close the scene (voxelConeTrace). A texel
// reaching back past the cone's origin would show what lies behind it (in a flat scene, the
// floor at the top face), and one wider than the cone what lies beside it (the top of a
// block): the face counts as closed only where the voxels at the exit point and across the
// scene from it, on the opposite face, are occupied (a room's floor and ceiling, not an open
// floor).
bool voxelSceneFaceOpen(vec3 p, vec3 origin, vec3 dir, int axis, float d)
{
  bool up = dir[axis] > 0.0;
  vec3 inward = vec3(0.0);
  inward[axis] = up ? -1.0 : 1.0;
  float face = up ? voxelSceneHi[axis] - 0.5 : voxelSceneLo[axis] + 0.5;
  float across = up ? voxelSceneLo[axis] + 0.5 : voxelSceneHi[axis] - 0.5;
  // (behind the origin: judged on the next level's texel, which the filtered read reaches)
  float reach = floor(face / (2.0 * d)) * 2.0 * d;
  vec3 exitPoint = p, oppositePoint = p;
  exitPoint[axis] = face;
  oppositePoint[axis] = across;
  return (up ? reach < origin[axis] : reach + 2.0 * d > origin[axis]) ||
    !(voxelOccupied(exitPoint) || voxelOccupied(exitPoint + inward)) ||
    !(voxelOccupied(oppositePoint) || voxelOccupied(oppositePoint - inward));
}

// The diameter of the texels a cone's sample at p, t voxels out, reads. Near the surface the
// cone starts from (voxelConeTrace), the largest texel whose reach stays above the surface's
// voxels; where even the finest level the caller may read (voxelMinLevel; the bounce, which
// writes the full-resolution volume, reads from level 1) would reach them, p is lifted along
// the normal to the lowest height a sample may be taken at: it still meets what stands beside
// the cone (the wall next to a floor), never the surface's own voxels.
float voxelConeFootprint(inout vec3 p, float t, float tanHalf, vec3 surface, vec3 surfaceNormal)
{
  float diameter = 2.0 * tanHalf * t;
  if (dot(surfaceNormal, surfaceNormal) > 0.0)
  {
    float finest = exp2(voxelMinLevel);
    float height = dot(p - surface, surfaceNormal);
    float lowest = 1.0 + 1.5 * finest;
    if (height < lowest)
    {
      p += surfaceNormal * (lowest - height);
      height = lowest;
    }
    diameter = min(diameter, exp2(floor(log2((height - 1.0) / 1.5))));
  }
  return max(diameter, 1.0);
}

// Front-to-back accumulation along a cone from `origin`, starting `start` voxels out:
// returns radiance (rgb) and opacity (a); `occlusion` gets the opacity weighted down with
// distance by `aoFalloff` (per voxel).
//
// A filtered sample of texel size s reaches texels up to 1.5 s away, and the surface's own
// voxels extend up to a voxel above it. So near the surface the cone starts from (plane
// through `surface` with unit normal `surfaceNormal`; a zero normal disables this) samples
// use the coarsest level whose reach, and that of the level blended with it, stays above the
// surface's voxels: a surface never shadows or lights itself.
vec4 voxelConeTrace(vec3 origin, vec3 dir, float tanHalf, float start, float maxDistance,
  float aoFalloff, vec3 surface, vec3 surfaceNormal, out float occlusion)
{
  vec4 acc = vec4(0.0);
  occlusion = 0.0;
  float res = float(voxelResolution);
  float stepFactor = max(coneStepFactor, 0.05);
  float t = max(start, 0.5);
  // Where the cone leaves the grid, or the scene's bounds through a face that a wall closes
  // (nothing lies beyond the bounds), its last sample is taken, half a voxel inside: a step
  // must not jump over the geometry between the last sample and the boundary (in a closed
  // room the walls lie there, and the cone would end short of full opacity: light lost).
  // That sample stands for everything up to the boundary, so it is read along the axis the
  // cone leaves through, whose directional mip holds the share of the footprint blocked
  // before that face (read obliquely, the other axes' mips see only part of a one-voxel
  // wall), and takes no step-length correction. At the scene's bounds it is centred on that
  // axis in the texels holding the boundary's voxels (not blended with the empty ones
  // beyond) and read along that axis alone (another axis' mip, read off
  // its own texels' centres, sees part of the wall): a room lower than it is wide has its
  // floor and ceiling deep inside the cubic grid. Where the face is open there, the cone goes
  // on to the grid's face. At the grid's faces, near an edge the axes whose faces lie within
  // one footprint of the exit share the read, so that neighbouring cones leaving through
  // different faces do not jump from one wall's colour to the other's. The step count is
  // bounded whatever the settings: no endless loops.
  vec3 safeDir = mix(dir, vec3(1e-6), lessThan(abs(dir), vec3(1e-6)));
  vec3 gridExits = max(-origin / safeDir, (vec3(res) - origin) / safeDir);
  vec3 exits = max((voxelSceneLo.xyz - origin) / safeDir, (voxelSceneHi.xyz - origin) / safeDir);
  float tExit = min(exits.x, min(exits.y, exits.z));
  int axis = exits.x == tExit ? 0 : (exits.y == tExit ? 1 : 2);
  // (a cone that starts outside the scene's bounds goes to the grid's face, as before them;
  // whether the face is open is decided once, where the last sample will be taken: a branch
  // in the loop that starts the cone over costs a third of the trace)
  vec3 pLast = origin + dir * (tExit - 0.5);
  float dLast = voxelConeFootprint(pLast, tExit - 0.5, tanHalf, surface, surfaceNormal);
  bool sceneFace = tExit > t && tExit < min(gridExits.x, min(gridExits.y, gridExits.z)) &&
    !voxelSceneFaceOpen(pLast, origin, dir, axis, voxelSceneFaceLevel(dLast));
  exits = sceneFace ? exits : gridExits;
  tExit = min(exits.x, min(exits.y, exits.z));
  float tEnd = min(maxDistance, tExit);
  bool last = false;
  float arrived = -1.0; // the step that led to this sample, in voxels
  for (int i = 0; i < 512 && !last && acc.a < 0.99; ++i)
  {
    if (t >= tEnd)
    {
      if (i == 0 || tEnd >= maxDistance)
      {
        break;
      }
      t = tEnd - 0.5;
      last = true;
    }
    vec3 p = origin + dir * t;
    if (any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(res))))
    {
      break;
    }
    float diameter = voxelConeFootprint(p, t, tanHalf, surface, surfaceNormal);
    vec3 readDir = dir;
    if (last && sceneFace)
    {
      diameter = voxelSceneFaceLevel(diameter);
      float face = dir[axis] > 0.0 ? voxelSceneHi[axis] - 0.5 : voxelSceneLo[axis] + 0.5;
      p[axis] = (floor(face / diameter) + 0.5) * diameter;
      readDir = vec3(0.0);
      readDir[axis] = sign(safeDir[axis]);
    }
    else if (last)
    {
      vec3 near = max(1.0 - (exits - tExit) / diameter, 0.0);
      readDir = sqrt(near / (near.x + near.y + near.z)) * sign(safeDir);
    }
    // (one call site: the sampler selection inside is large, and so is its compiled code)
    vec4 s = voxelSampleCone(p, diameter, readDir);
    // Opacity correction for steps shorter or longer than the sample's extent, by the step
    // that led here: where the footprint grew, corrected for its own diameter the sample
    // would count again the span its predecessor covered (a compact emitter twice). At the
    // scene's bounds the last sample's opacity is the share of the footprint blocked up to
    // the face, which the earlier samples' filters have partly seen already: it raises the
    // cone's opacity to its own, never adds to it (an emitter at the face would count twice).
    float exponent = arrived < 0.0 ? stepFactor : min(arrived / diameter, stepFactor);
    float a = !last ? 1.0 - pow(clamp(1.0 - s.a, 0.0, 1.0), exponent)
                    : (sceneFace ? clamp((s.a - acc.a) / max(1.0 - acc.a, 1e-4), 0.0, 1.0)
                                 : clamp(s.a, 0.0, 1.0));
    vec3 c = s.a > 1e-4 ? s.rgb * (a / s.a) : vec3(0.0);
    acc.rgb += (1.0 - acc.a) * c;
    acc.a += (1.0 - acc.a) * a;
    occlusion += (1.0 - occlusion) * a / (1.0 + aoFalloff * t);
    arrived = diameter * stepFactor;
    t += arrived;
  }
  return acc;
}

// An orthonormal basis around unit n (Duff et al. 2017), for placing cones around a normal.
void voxelBasis(vec3 n, out vec3 t, out vec3 b)
{
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}
