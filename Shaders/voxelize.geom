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
#include "voxel_triangle.glsl"
uniform int voxelDilate;       // 0 when the hardware rasterizes conservatively

// The triangle (voxel_triangle.glsl) for the fragment stage.
flat out int voxelAxis;
flat out vec4 voxelBox;
flat out vec3 voxelPlane;
flat out vec2 voxelDepthRange;
flat out vec3 voxelEdge0;
flat out vec3 voxelEdge1;
flat out vec3 voxelEdge2;
flat out vec3 voxelFaceNormal;

vec3 voxelBary;

void main()
{
  vec3 p[3];
  for (int k = 0; k < 3; ++k)
  {
    p[k] = (gl_in[k].gl_Position.xyz / gl_in[k].gl_Position.w * 0.5 + 0.5) * float(voxelResolution);
  }
  VoxelTriangle t;
  vec3 q[3];
  vec2 v[3];
  float area2;
  if (!voxelTriangleSetup(p, t, q, v, area2))
  {
    return;
  }
  vec3 edges[3] = vec3[3](t.edge0, t.edge1, t.edge2);
  vec3 lines[3];
  for (int k = 0; k < 3; ++k)
  {
    // Half the pixel diagonal along the normal, plus a little for rasterization ties.
    vec2 en = edges[k].xy;
    lines[k] = vec3(en, edges[k].z - 0.5 * (abs(en.x) + abs(en.y)) - 1e-3 * length(en));
  }
  vec2 bmin = t.box.xy;
  vec2 bmax = t.box.zw;

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

  voxelAxis = t.axis;
  voxelBox = t.box;
  voxelPlane = t.plane;
  voxelDepthRange = t.depthRange;
  voxelEdge0 = t.edge0;
  voxelEdge1 = t.edge1;
  voxelEdge2 = t.edge2;
  voxelFaceNormal = t.faceNormal;

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
    voxelBary = voxelBarycentric(q, area2, c);

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
