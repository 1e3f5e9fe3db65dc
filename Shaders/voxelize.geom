//VTK::System::Dec
#extension GL_ARB_shading_language_420pack : require
// Voxelization geometry shader, injected into VTK's polydata mapper by vtkVoxelGIPass.
//
// Input positions are in the normalized device coordinates of the voxel grid cube (the pass
// renders with an orthographic camera fitted to the grid). Each triangle is projected along
// its dominant axis, then dilated for conservative rasterization (Hasselgren et al., GPU Gems 2
// ch. 42): every edge moves out by the pixel's half diagonal along its normal. Where the
// dilated vertices run away (very acute angles) a triangle enclosing the bounding rectangle
// (grown by half a pixel) is emitted instead: one primitive, so no pixel is covered twice even
// by a conservative rasterizer. The fragment stage clips against the exact triangle, so both
// shapes are correct.
// Where the GPU rasterizes conservatively itself (GL_NV_conservative_raster), well-shaped
// triangles are emitted as they are; slivers, which the hardware may cull as degenerate, still
// get the enclosing triangle.
//
// VTK fills the //VTK:: tags below with its varyings written as `xVSOutput[i]`; the pass
// rewrites those into barycentric blends so attributes stay exact on the dilated shape.

//VTK::PositionVC::Dec
//VTK::PrimID::Dec
//VTK::Color::Dec
//VTK::Normal::Dec
//VTK::Light::Dec
//VTK::TCoord::Dec
//VTK::Picking::Dec
//VTK::DepthPeeling::Dec
//VTK::Clip::Dec
//VTK::Output::Dec

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

#include "voxel_grid.glsl"
uniform int voxelDilate;       // 0 when the hardware rasterizes conservatively

flat out int voxelAxis;        // 0: x, 1: y, 2: z dominant
flat out vec4 voxelBox;        // triangle bounds in the projected plane (voxel units)
flat out vec3 voxelPlane;      // depth plane: z' = a x' + b y' + c
flat out vec2 voxelDepthRange; // triangle's depth range
flat out vec3 voxelEdge0;      // edge functions n.x x + n.y y + d, inside <= 0
flat out vec3 voxelEdge1;
flat out vec3 voxelEdge2;
flat out vec3 voxelFaceNormal; // unit geometric normal in grid space

vec3 voxelBary;

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

void main()
{
  vec3 p[3];
  for (int k = 0; k < 3; ++k)
  {
    p[k] = (gl_in[k].gl_Position.xyz / gl_in[k].gl_Position.w * 0.5 + 0.5) * float(voxelResolution);
    if (!voxelFinite(p[k]))
    {
      return;
    }
  }
  vec3 n = cross(p[1] - p[0], p[2] - p[0]);
  vec3 an = abs(n);
  float nmax = max(an.x, max(an.y, an.z));
  // Zero-area triangles have no surface to voxelize.
  if (!(nmax > 1e-12))
  {
    return;
  }
  int axis = (an.x >= an.y && an.x >= an.z) ? 0 : (an.y >= an.z ? 1 : 2);
  vec3 q[3];
  for (int k = 0; k < 3; ++k)
  {
    q[k] = voxelSwizzle(p[k], axis);
  }
  vec3 nq = voxelSwizzle(n, axis);
  float area2 = voxelCross2(q[1].xy - q[0].xy, q[2].xy - q[0].xy);

  // Counter-clockwise order in the projected plane, so culling never drops the triangle.
  int order[3];
  order[0] = 0;
  order[1] = area2 > 0.0 ? 1 : 2;
  order[2] = area2 > 0.0 ? 2 : 1;
  vec2 v[3];
  for (int k = 0; k < 3; ++k)
  {
    v[k] = q[order[k]].xy;
  }

  vec3 lines[3];
  vec3 edges[3];
  for (int k = 0; k < 3; ++k)
  {
    vec2 e = v[(k + 1) % 3] - v[k];
    vec2 en = vec2(e.y, -e.x);
    float d = -dot(en, v[k]);
    edges[k] = vec3(en, d);
    // Half the pixel diagonal along the normal, plus a little for rasterization ties.
    float offset = 0.5 * (abs(en.x) + abs(en.y)) + 1e-3 * length(en);
    lines[k] = vec3(en, d - offset);
  }

  vec2 bmin = min(v[0], min(v[1], v[2]));
  vec2 bmax = max(v[0], max(v[1], v[2]));

  vec2 dilated[3];
  bool useTriangle = true;
  for (int k = 0; k < 3; ++k)
  {
    vec3 h = cross(lines[(k + 2) % 3], lines[k]);
    dilated[k] = voxelDilate != 0 ? h.xy / h.z : v[k];
    if (!(abs(h.z) > 1e-12) || any(lessThan(h.xy / h.z, bmin - 1.0)) ||
      any(greaterThan(h.xy / h.z, bmax + 1.0)))
    {
      useTriangle = false;
    }
  }

  voxelAxis = axis;
  voxelBox = vec4(bmin, bmax);
  voxelPlane = vec3(-nq.xy / nq.z, dot(nq, q[0]) / nq.z);
  voxelDepthRange = vec2(min(q[0].z, min(q[1].z, q[2].z)), max(q[0].z, max(q[1].z, q[2].z)));
  voxelEdge0 = edges[0];
  voxelEdge1 = edges[1];
  voxelEdge2 = edges[2];
  voxelFaceNormal = n / length(n);

  vec2 corners[3];
  if (useTriangle)
  {
    corners[0] = dilated[0];
    corners[1] = dilated[1];
    corners[2] = dilated[2];
  }
  else
  {
    // Right triangle with legs of twice the grown rectangle: contains it with margin.
    vec2 lo = bmin - 0.501;
    vec2 size = 2.0 * (bmax + 0.501 - lo) + 1.0;
    corners[0] = lo;
    corners[1] = lo + vec2(size.x, 0.0);
    corners[2] = lo + vec2(0.0, size.y);
  }

  for (int j = 0; j < 3; ++j)
  {
    vec2 c = corners[j];
    // Barycentric weights of c with respect to the original (unordered) triangle.
    float b0 = voxelCross2(q[1].xy - c, q[2].xy - c) / area2;
    float b1 = voxelCross2(q[2].xy - c, q[0].xy - c) / area2;
    voxelBary = vec3(b0, b1, 1.0 - b0 - b1);

    //VTK::PrimID::Impl
    //VTK::Clip::Impl
    //VTK::Color::Impl
    //VTK::Normal::Impl
    //VTK::Light::Impl
    //VTK::TCoord::Impl
    //VTK::DepthPeeling::Impl
    //VTK::Picking::Impl
    //VTK::PositionVC::Impl

    gl_Position = vec4(c / float(voxelResolution) * 2.0 - 1.0, 0.0, 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
