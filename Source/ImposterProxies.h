/**
 * ImposterProxies: points VTK draws as spheres (vtkProperty::RenderPointsAsSpheres: vedo's and
 * PyVista's point clouds) and lines it draws as tubes (RenderLinesAsTubes: streamlines)
 * voxelized as the spheres and cylinders they show. VTK draws each point as a shaded sprite of
 * the point size in pixels, and each line as a shaded strip of the line width in pixels, with no
 * triangles to voxelize; for each such actor a proxy actor glyphs a sphere at every point
 * (vtkGlyph3DMapper) or sweeps a tube along every line (vtkTubeFilter), with the actor's
 * colouring, property and matrix, of the radius the imposters show in world units at the actor's
 * distance from the camera, so that the voxelization, the shadow maps and the scan treat it as
 * any glyphed or polygonal actor. The proxy is rebuilt when the actor, its mapper or input
 * changed, or when that radius moved by more than a quarter (a zoom; camera moves within that
 * keep the voxels). GL-free.
 */
#ifndef VoxelGIImposterProxies_h
#define VoxelGIImposterProxies_h

#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkType.h"         // for vtkMTimeType

#include <set>
#include <string>
#include <unordered_map>

class vtkActor;
class vtkPolyData;
class vtkProp;
class vtkRenderer;

namespace voxelgi
{

class ImposterProxies
{
public:
  /// Whether `actor` draws the points of a polydata input as spheres, or its lines as tubes
  /// (and nothing with an area).
  static bool Applies(vtkActor* actor);
  /// The world radius of the spheres or tubes `actor` shows in `renderer` now: half the point
  /// size or line width in pixels at the distance of the actor's centre from the camera.
  static double WorldRadius(vtkActor* actor, vtkRenderer* renderer);
  /// The up-to-date proxy of `actor` (Applies()) whose signature the scan found, or null
  /// with `reason` when its input has no points.
  vtkActor* Update(vtkActor* actor, vtkMTimeType signature, vtkRenderer* renderer,
    std::string& reason);
  /// Drop the proxies of actors not in `kept`.
  void Retain(const std::set<vtkProp*>& kept);

private:
  struct Proxy
  {
    vtkSmartPointer<vtkActor> Actor;
    vtkMTimeType Synced = 0;
    double Radius = 0.0;
  };
  /// The polydata `actor`'s mapper draws (null for glyph mappers, which keep their path).
  static vtkPolyData* Input(vtkActor* actor);
  static bool Spheres(vtkActor* actor);
  static bool Tubes(vtkActor* actor);
  static void Build(vtkActor* actor, vtkActor* proxy, double radius);

  std::unordered_map<vtkActor*, Proxy> Proxies;
};

}

#endif
