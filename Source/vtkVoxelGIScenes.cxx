#include "vtkVoxelGIScenes.h"

#include "vtkVoxelGIPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <array>

vtkStandardNewMacro(vtkVoxelGIScenes);

namespace
{
constexpr double Size = 5.5;

// A quad from `origin` spanned by p1 and p2; its normal (p1 - o) x (p2 - o) faces the inside.
using Vec3 = std::array<double, 3>;

vtkActor* AddQuad(vtkRenderer* renderer, const Vec3& o, const Vec3& p1, const Vec3& p2,
  const Vec3& color)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(o[0], o[1], o[2]);
  plane->SetPoint1(p1[0], p1[1], p1[2]);
  plane->SetPoint2(p2[0], p2[1], p2[2]);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  renderer->AddActor(actor);
  return actor;
}

void AddBlock(vtkRenderer* renderer, double cx, double cz, double sx, double sy, double sz,
  double angle, const Vec3& color)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(sx);
  cube->SetYLength(sy);
  cube->SetZLength(sz);
  vtkNew<vtkTransform> transform;
  transform->Translate(cx, 0.5 * sy, cz);
  transform->RotateY(angle);
  vtkNew<vtkTransformPolyDataFilter> place;
  place->SetInputConnection(cube->GetOutputPort());
  place->SetTransform(transform);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(place->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  renderer->AddActor(actor);
}
}

void vtkVoxelGIScenes::AddCornellBox(vtkRenderer* renderer, double panelEmission)
{
  if (!renderer)
  {
    return;
  }
  const Vec3 white{ { 0.75, 0.75, 0.75 } };
  const Vec3 red{ { 0.75, 0.1, 0.1 } };
  const Vec3 green{ { 0.1, 0.6, 0.1 } };
  const double S = Size;

  const Vec3 o{ { 0, 0, 0 } };
  // floor (y = 0, normal +y), ceiling (y = S, normal -y), back wall (z = 0, normal +z)
  AddQuad(renderer, o, { 0, 0, S }, { S, 0, 0 }, white);
  AddQuad(renderer, { 0, S, 0 }, { S, S, 0 },
    { 0, S, S }, white);
  AddQuad(renderer, o, { S, 0, 0 }, { 0, S, 0 }, white);
  // left wall (x = 0, normal +x) red; right wall (x = S, normal -x) green
  AddQuad(renderer, o, { 0, S, 0 }, { 0, 0, S }, red);
  AddQuad(renderer, { S, 0, 0 }, { S, 0, S },
    { S, S, 0 }, green);

  AddBlock(renderer, 3.7, 2.0, 1.65, 1.65, 1.65, -17.0, white);
  AddBlock(renderer, 1.9, 3.4, 1.65, 3.3, 1.65, 15.0, white);

  // Emissive ceiling panel, a little below the ceiling, facing down.
  const double a = 0.38 * S, b = 0.62 * S, y = S - 0.01;
  vtkActor* panel = AddQuad(renderer, { a, y, a }, { b, y, a },
    { a, y, b }, { 1.0, 1.0, 1.0 });
  panel->GetProperty()->SetAmbient(1.0);
  panel->GetProperty()->SetDiffuse(0.0);
  vtkVoxelGIPass::SetPropEmission(panel, panelEmission, panelEmission, 0.85 * panelEmission);

  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetPosition(0.5 * S, S - 0.3, 0.5 * S);
  light->SetFocalPoint(0.5 * S, 0.0, 0.5 * S);
  light->SetConeAngle(90.0);
  light->SetColor(1.0, 0.95, 0.85);
  light->SetIntensity(1.0);
  renderer->AddLight(light);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.5 * S, 0.5 * S, 0.5 * S);
  camera->SetPosition(0.5 * S, 0.5 * S, 2.9 * S);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(30.0);
  renderer->ResetCameraClippingRange();
}

void vtkVoxelGIScenes::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
