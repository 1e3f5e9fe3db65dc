// Compute voxelization: the triangles of an actor's GPU-resident copy (SceneBuffers: its
// positions and colours, uploaded when its data changes) go into the same accumulators by the
// same rule (voxel_triangle.glsl, voxel_write.glsl) as the raster path through VTK's mappers,
// without a VTK draw per actor and without the raster pipeline (on GH100 GPUs only 4 of 132
// SMs rasterize). voxelLargePass 0: a thread per triangle writes the pixel columns of its
// projection when they are few and lists the triangle otherwise; 1: a work group per listed
// triangle shares its columns (a wall of the Cornell box covers thousands).
layout(local_size_x = 64) in;

#include "voxel_triangle.glsl"
#include "voxel_write.glsl"
#include "scene_buffers.glsl"

// Three vertex indices per triangle; for per-cell colouring, each triangle's RGBA8 colour.
layout(std430, binding = VOXELGI_SCENE_INDEX_BINDING) readonly buffer VoxelIndexBuffer
{
  uint voxelIndices[];
};
layout(std430, binding = VOXELGI_SCENE_CELL_COLOR_BINDING) readonly buffer VoxelCellColorBuffer
{
  uint voxelCellColors[];
};

// At voxelLargeSlot: (groups, 1, 1, count), the indirect dispatch of the actor's listed
// triangles; at voxelLargeBase: the list.
layout(std430, binding = VOXELGI_LARGE_TRIANGLE_BINDING) buffer VoxelLargeBuffer
{
  uint voxelLarge[];
};

uniform mat4 voxelGridFromModel;
uniform uint voxelTriangleCount;
uniform int voxelColorMode;  // 0: the actor's colour, 1: per vertex, 2: per triangle (cell)
uniform vec4 voxelColor;     // diffuse coefficient times the actor's diffuse colour; opacity
uniform float voxelDiffuse;  // diffuse coefficient: scales scalar colours, as in VTK's shader
uniform int voxelLargePass;
uniform uint voxelLargeSlot;
uniform uint voxelLargeBase;

const uint voxelLargeColumns = 16u;
const uint voxelMaxGroups = 65535u;

bool voxelLoad(uint index, out VoxelTriangle t, out vec3 q[3], out float area2, out uvec4 tri)
{
  tri = uvec4(voxelIndices[3u * index], voxelIndices[3u * index + 1u],
    voxelIndices[3u * index + 2u], voxelColorMode == 2 ? voxelCellColors[index] : 0u);
  vec3 p[3];
  for (int k = 0; k < 3; ++k)
  {
    p[k] = (voxelGridFromModel * vec4(voxelVertices[tri[k]].position, 1.0)).xyz;
  }
  vec2 v[3];
  return voxelTriangleSetup(p, t, q, v, area2);
}

// The unlit colour VTK's fragment shader computes at the projected point `c`.
vec4 voxelColorAt(uvec4 tri, vec3 q[3], float area2, vec2 c)
{
  if (voxelColorMode == 1)
  {
    vec3 b = voxelBarycentric(q, area2, c);
    vec4 color = b.x * unpackUnorm4x8(voxelVertices[tri.x].color) +
      b.y * unpackUnorm4x8(voxelVertices[tri.y].color) +
      b.z * unpackUnorm4x8(voxelVertices[tri.z].color);
    return vec4(voxelDiffuse * color.rgb, color.a);
  }
  if (voxelColorMode == 2)
  {
    vec4 color = unpackUnorm4x8(tri.w);
    return vec4(voxelDiffuse * color.rgb, color.a);
  }
  return voxelColor;
}

// The pixel columns of the grid the projection may touch: [lo, hi] on each axis.
void voxelColumns(VoxelTriangle t, out ivec2 lo, out ivec2 hi)
{
  lo = max(ivec2(floor(t.box.xy - 1.0)), ivec2(0));
  hi = min(ivec2(floor(t.box.zw + 1.0)), ivec2(voxelResolution - 1));
}

// Columns first, first + stride, ... of triangle `index`; `mayList`: list it instead when it
// has many.
void voxelWriteColumns(uint index, uint first, uint stride, bool mayList)
{
  VoxelTriangle t;
  vec3 q[3];
  float area2;
  uvec4 tri;
  if (!voxelLoad(index, t, q, area2, tri))
  {
    return;
  }
  ivec2 lo;
  ivec2 hi;
  voxelColumns(t, lo, hi);
  if (any(greaterThan(lo, hi)))
  {
    return;
  }
  uint width = uint(hi.x - lo.x + 1);
  uint columns = width * uint(hi.y - lo.y + 1);
  if (mayList && columns > voxelLargeColumns)
  {
    uint k = atomicAdd(voxelLarge[voxelLargeSlot + 3u], 1u);
    atomicMax(voxelLarge[voxelLargeSlot], min(k + 1u, voxelMaxGroups));
    voxelLarge[voxelLargeBase + k] = index;
    return;
  }
  for (uint i = first; i < columns; i += stride)
  {
    vec2 c = vec2(lo + ivec2(i % width, i / width)) + 0.5;
    voxelWriteColumn(t, c, voxelColorAt(tri, q, area2, c));
  }
}

void main()
{
  if (voxelLargePass == 0)
  {
    uint index = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x +
      gl_LocalInvocationID.x;
    if (index < voxelTriangleCount)
    {
      voxelWriteColumns(index, 0u, 1u, true);
    }
    return;
  }
  uint count = voxelLarge[voxelLargeSlot + 3u];
  for (uint entry = gl_WorkGroupID.x; entry < count; entry += gl_NumWorkGroups.x)
  {
    voxelWriteColumns(
      voxelLarge[voxelLargeBase + entry], gl_LocalInvocationID.x, gl_WorkGroupSize.x, false);
  }
}
