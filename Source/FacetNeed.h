/**
 * FacetNeed: whether VTK shades an actor's surface with normals that lean off its triangles
 * (point normals interpolated over a curved mesh: isosurfaces, spheres), where the trace needs
 * the triangles' own planes from the G-buffer (a cone around a leaning normal may point into
 * the surface). A surface shaded flat, without point normals, or with point normals that are
 * its triangles' own (boxes, planes) does not: the G-buffer leaves that attachment out of
 * its draws. Decided from up to 64 of the input's polygons, kept until the input changes;
 * actors it cannot read (other mappers, composite data) need it. GL-free.
 */
#ifndef VoxelGIFacetNeed_h
#define VoxelGIFacetNeed_h

#include "vtkType.h" // for vtkMTimeType

#include <unordered_map>

class vtkActor;
class vtkPolyData;

namespace voxelgi
{

class FacetNeed
{
public:
  /// Whether the surface `actor` draws needs its triangles' planes in the G-buffer.
  bool Needs(vtkActor* actor);
  /// Whether the point normals of `polyData` lean more than about 3 degrees off the plane of
  /// one of its sampled polygons (either side).
  static bool NormalsLean(vtkPolyData* polyData);

private:
  struct Entry
  {
    vtkMTimeType Time = 0;
    bool Leans = true;
  };
  std::unordered_map<vtkPolyData*, Entry> Inputs;
};

}

#endif
