// Voxelization fragment code, inserted by vtkVoxelGIPass into VTK's polydata fragment shader
// (before main); main ends with voxelWrite(<the colour VTK computed, unlit>).
#include "voxel_triangle.glsl"
#include "voxel_write.glsl"

// The triangle, from voxelize.geom.
flat in int voxelAxis;
flat in vec4 voxelBox;
flat in vec3 voxelPlane;
flat in vec2 voxelDepthRange;
flat in vec3 voxelEdge0;
flat in vec3 voxelEdge1;
flat in vec3 voxelEdge2;
flat in vec3 voxelFaceNormal;

void voxelWrite(vec4 color)
{
  VoxelTriangle t = VoxelTriangle(voxelAxis, voxelBox, voxelPlane, voxelDepthRange, voxelEdge0,
    voxelEdge1, voxelEdge2, voxelFaceNormal);
  voxelWriteColumn(t, floor(gl_FragCoord.xy) + 0.5, color);
}
