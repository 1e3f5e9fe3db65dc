#include "ImposterProxies.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkGlyph3DMapper.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTubeFilter.h"

#include <cmath>

namespace voxelgi
{

bool ImposterProxies::Applies(vtkActor* actor)
{
  return Spheres(actor) || Tubes(actor);
}

vtkPolyData* ImposterProxies::Input(vtkActor* actor)
{
  vtkMapper* mapper = actor->GetMapper();
  return mapper && !mapper->IsA("vtkGlyph3DMapper")
    ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0))
    : nullptr;
}

bool ImposterProxies::Spheres(vtkActor* actor)
{
  vtkProperty* property = actor->GetProperty();
  vtkPolyData* input = Input(actor);
  if (!input || !property->GetRenderPointsAsSpheres())
  {
    return false;
  }
  // Points representation: every point; surface representation: its vertex cells, when it
  // has nothing else (lines and polygons keep their own notice or path).
  return property->GetRepresentation() == VTK_POINTS ||
    (property->GetRepresentation() == VTK_SURFACE && input->GetNumberOfVerts() > 0 &&
      input->GetNumberOfLines() + input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0);
}

bool ImposterProxies::Tubes(vtkActor* actor)
{
  vtkProperty* property = actor->GetProperty();
  vtkPolyData* input = Input(actor);
  // Lines with nothing of area beside them (a surface's edges keep the surface's path).
  return input && property->GetRenderLinesAsTubes() &&
    property->GetRepresentation() != VTK_POINTS && input->GetNumberOfLines() > 0 &&
    input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0;
}

double ImposterProxies::WorldRadius(vtkActor* actor, vtkRenderer* renderer)
{
  const int* size = renderer->GetSize();
  const double height = size && size[1] > 0 ? size[1] : 300.0;
  vtkCamera* camera = renderer->GetActiveCamera();
  double centre[3];
  const double* b = actor->GetBounds();
  for (int i = 0; i < 3; ++i)
  {
    centre[i] = vtkMath::AreBoundsInitialized(b) ? 0.5 * (b[2 * i] + b[2 * i + 1]) : 0.0;
  }
  const double distance = std::sqrt(vtkMath::Distance2BetweenPoints(camera->GetPosition(), centre));
  const double viewHeight = camera->GetParallelProjection()
    ? 2.0 * camera->GetParallelScale()
    : 2.0 * distance * std::tan(vtkMath::RadiansFromDegrees(0.5 * camera->GetViewAngle()));
  vtkProperty* property = actor->GetProperty();
  const double pixels = Tubes(actor) ? property->GetLineWidth() : property->GetPointSize();
  return 0.5 * pixels * viewHeight / height;
}

vtkActor* ImposterProxies::Update(
  vtkActor* actor, vtkMTimeType signature, vtkRenderer* renderer, std::string& reason)
{
  vtkPolyData* input = Input(actor);
  if (!input || input->GetNumberOfPoints() == 0)
  {
    reason = std::string(actor->GetClassName()) + " (" +
      (Tubes(actor) ? "lines drawn as tubes" : "points drawn as spheres") + ", but no points)";
    this->Proxies.erase(actor);
    return nullptr;
  }
  const double radius = WorldRadius(actor, renderer);
  Proxy& proxy = this->Proxies[actor];
  const bool zoomed = !(radius > 0.75 * proxy.Radius && radius < 1.25 * proxy.Radius);
  if (!proxy.Actor || proxy.Synced != signature || zoomed)
  {
    if (!proxy.Actor)
    {
      proxy.Actor = vtkSmartPointer<vtkActor>::New();
    }
    Build(actor, proxy.Actor, radius);
    proxy.Synced = signature;
    proxy.Radius = radius;
  }
  return proxy.Actor;
}

void ImposterProxies::Build(vtkActor* actor, vtkActor* proxy, double radius)
{
  vtkMapper* mapper = actor->GetMapper();
  vtkPolyData* input = Input(actor);
  vtkSmartPointer<vtkMapper> shapes;
  if (Tubes(actor))
  {
    // Each line as the cylinder its imposter shows, the lines' point data carried along.
    vtkNew<vtkTubeFilter> tubes;
    tubes->SetInputData(input);
    tubes->SetRadius(radius);
    tubes->SetNumberOfSides(8);
    tubes->CappingOn();
    auto polygons = vtkSmartPointer<vtkPolyDataMapper>::New();
    // The actor's colouring: lookup table, scalar mode and range, array selection.
    polygons->vtkMapper::ShallowCopy(mapper);
    polygons->SetInputConnection(tubes->GetOutputPort());
    shapes = polygons;
  }
  else
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetRadius(radius);
    sphere->SetThetaResolution(12);
    sphere->SetPhiResolution(8);
    auto glyphs = vtkSmartPointer<vtkGlyph3DMapper>::New();
    glyphs->vtkMapper::ShallowCopy(mapper);
    glyphs->SetInputData(input);
    glyphs->SetSourceConnection(sphere->GetOutputPort());
    glyphs->ScalingOff();
    glyphs->OrientOff();
    shapes = glyphs;
  }
  proxy->SetMapper(shapes);
  proxy->GetProperty()->DeepCopy(actor->GetProperty());
  proxy->GetProperty()->SetRepresentationToSurface();
  proxy->GetProperty()->SetRenderPointsAsSpheres(false);
  proxy->GetProperty()->SetRenderLinesAsTubes(false);
  vtkNew<vtkMatrix4x4> matrix;
  matrix->DeepCopy(actor->GetMatrix());
  proxy->SetUserMatrix(matrix);
  proxy->Modified();
}

void ImposterProxies::Retain(const std::set<vtkProp*>& kept)
{
  for (auto it = this->Proxies.begin(); it != this->Proxies.end();)
  {
    it = kept.count(it->first) ? std::next(it) : this->Proxies.erase(it);
  }
}

}
