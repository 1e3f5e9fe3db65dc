/**
 * ImposterProxies: shapes VTK draws as shaded sprites without triangles, voxelized as the
 * spheres and cylinders they show. Points drawn as spheres (vtkProperty::RenderPointsAsSpheres:
 * vedo's and PyVista's point clouds) and lines drawn as tubes (RenderLinesAsTubes: streamlines)
 * are sprites of the point size or line width in pixels: their proxy glyphs a sphere at every
 * point (vtkGlyph3DMapper) or sweeps a tube along every line (vtkTubeFilter), with the actor's
 * colouring, of the radius the imposters show in world units at the actor's distance from the
 * camera, rebuilt when that radius moved by more than a quarter (a zoom). A
 * vtkPointGaussianMapper with a splat shape (SplatShaderCode, as ParaView's sphere preset: the
 * shape within the splat's radius) is glyphed spheres of the splats' radii (ScaleFactor, times
 * the ScaleArray's value through the ScaleFunction when set); a vtkMoleculeMapper's atoms and
 * bonds are spheres of its atomic radii and cylinders of its bond radius, in the colours it
 * gives them. Each proxy carries the actor's property and matrix, so that the voxelization, the
 * shadow maps and the scan treat it as any glyphed or polygonal actor; it is rebuilt when the
 * actor, its mapper or input changed. GL-free.
 */
#ifndef VoxelGIImposterProxies_h
#define VoxelGIImposterProxies_h

#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkType.h"         // for vtkMTimeType

#include <set>
#include <string>
#include <unordered_map>

class vtkActor;
class vtkMapper;
class vtkPolyData;
class vtkProp;
class vtkRenderer;

namespace voxelgi
{

class ImposterProxies
{
public:
  /// Whether `actor` draws the points of a polydata input as spheres, or its lines as tubes
  /// (and nothing with an area), or is drawn by a splat or molecule mapper (below).
  static bool Applies(vtkActor* actor);
  /// Whether `actor` is drawn by a vtkPointGaussianMapper with splats of a shape
  /// (SplatShaderCode) and a radius (ScaleFactor > 0).
  static bool Splats(vtkActor* actor);
  /// Whether `actor` is drawn by a vtkMoleculeMapper with a molecule.
  static bool Molecule(vtkActor* actor);
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
  static vtkSmartPointer<vtkMapper> SphereShapes(vtkActor* actor, double radius);
  static vtkSmartPointer<vtkMapper> TubeShapes(vtkActor* actor, double radius);
  static vtkSmartPointer<vtkMapper> SplatShapes(vtkActor* actor);
  static vtkSmartPointer<vtkMapper> MoleculeShapes(vtkActor* actor);

  std::unordered_map<vtkActor*, Proxy> Proxies;
};

}

#endif
