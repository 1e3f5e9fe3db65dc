// One triangle as both voxelization paths see it (voxelize.geom through VTK's mappers,
// voxelize.comp from the scene's buffers): projected along its dominant axis, with the
// bounds, edge functions and depth plane that decide which voxels it touches
// (voxel_write.glsl). Shared so that both paths give the same voxels.

struct VoxelTriangle
{
  int axis;          // 0: x, 1: y, 2: z dominant
  vec4 box;          // bounds in the projected plane (voxel units)
  vec3 plane;        // depth plane: z' = a x' + b y' + c
  vec2 depthRange;   // the triangle's depth range
  vec3 edge0;        // edge functions n.x x + n.y y + d, inside <= 0 (counter-clockwise)
  vec3 edge1;
  vec3 edge2;
  vec3 faceNormal;   // unit geometric normal in grid space
};

vec3 voxelSwizzle(vec3 p, int axis)
{
  return axis == 0 ? p.yzx : (axis == 1 ? p.zxy : p);
}

float voxelCross2(vec2 a, vec2 b)
{
  return a.x * b.y - a.y * b.x;
}

bool voxelFinite(vec3 v)
{
  return !any(isnan(v)) && !any(isinf(v));
}

// Sets up the triangle `p` (grid coordinates). `q`: its vertices projected (unordered),
// `v`: the projected corners in counter-clockwise order, `area2`: twice the signed projected
// area of `q`. False for non-finite or zero-area triangles, which add no voxels.
bool voxelTriangleSetup(vec3 p[3], out VoxelTriangle t, out vec3 q[3], out vec2 v[3],
                        out float area2)
{
  for (int k = 0; k < 3; ++k)
  {
    if (!voxelFinite(p[k]))
    {
      return false;
    }
  }
  vec3 n = cross(p[1] - p[0], p[2] - p[0]);
  vec3 an = abs(n);
  float nmax = max(an.x, max(an.y, an.z));
  if (!(nmax > 1e-12))
  {
    return false;
  }
  t.axis = (an.x >= an.y && an.x >= an.z) ? 0 : (an.y >= an.z ? 1 : 2);
  for (int k = 0; k < 3; ++k)
  {
    q[k] = voxelSwizzle(p[k], t.axis);
  }
  vec3 nq = voxelSwizzle(n, t.axis);
  area2 = voxelCross2(q[1].xy - q[0].xy, q[2].xy - q[0].xy);
  // Counter-clockwise order in the projected plane, so culling never drops the triangle.
  v[0] = q[0].xy;
  v[1] = area2 > 0.0 ? q[1].xy : q[2].xy;
  v[2] = area2 > 0.0 ? q[2].xy : q[1].xy;
  vec3 edges[3];
  for (int k = 0; k < 3; ++k)
  {
    vec2 e = v[(k + 1) % 3] - v[k];
    vec2 en = vec2(e.y, -e.x);
    edges[k] = vec3(en, -dot(en, v[k]));
  }
  t.edge0 = edges[0];
  t.edge1 = edges[1];
  t.edge2 = edges[2];
  vec2 bmin = min(v[0], min(v[1], v[2]));
  vec2 bmax = max(v[0], max(v[1], v[2]));
  t.box = vec4(bmin, bmax);
  t.plane = vec3(-nq.xy / nq.z, dot(nq, q[0]) / nq.z);
  t.depthRange = vec2(min(q[0].z, min(q[1].z, q[2].z)), max(q[0].z, max(q[1].z, q[2].z)));
  t.faceNormal = n / length(n);
  return true;
}

// Barycentric weights of the projected point `c` with respect to the unordered `q`.
vec3 voxelBarycentric(vec3 q[3], float area2, vec2 c)
{
  float b0 = voxelCross2(q[1].xy - c, q[2].xy - c) / area2;
  float b1 = voxelCross2(q[2].xy - c, q[0].xy - c) / area2;
  return vec3(b0, b1, 1.0 - b0 - b1);
}
