// Points drawn as spheres (RenderPointsAsSpheres) against the same spheres as polygons: a
// cloud of 150 points of 10 pixels over a floor under a sun, and the same points glyphed with
// polygonal spheres of the radius the sprites show (half the point size in pixels at the
// cloud centre's distance from the camera: VTK's sprites are that many pixels across). Their
// voxel occupancy above the floor and the ambient occlusion of the floor below them agree
// within 5 %.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3D.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace
{
using glm::dvec3;
constexpr int Size = 200;
constexpr double PointSize = 10.0;
const dvec3 Eye(0.0, 6.0, 12.0), Centre(0.0, 2.0, 0.0);

struct Measured
{
  int Occupied = 0;     // voxels above the floor
  double FloorAO = 0.0; // mean AO of the floor's pixels below the cloud
};

/// 150 points in a ball of radius 1.5 around Centre (a fixed sequence).
vtkSmartPointer<vtkPolyData> Cloud()
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> verts;
  while (points->GetNumberOfPoints() < 150)
  {
    double p[3];
    for (double& c : p)
    {
      c = random->GetRangeValue(-1.5, 1.5);
      random->Next();
    }
    if (vtkMath::Norm(p) <= 1.5)
    {
      verts->InsertNextCell(1);
      verts->InsertCellPoint(points->InsertNextPoint(p[0], p[1] + Centre.y, p[2]));
    }
  }
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  cloud->SetVerts(verts);
  return cloud;
}

/// Render the cloud over the floor as sprites or as polygonal spheres of `radius`.
bool Measure(vtkPolyData* cloud, bool polygons, double radius, Measured& m)
{
  voxelgi_test::GIWindow view(nullptr, 64, Size, 0);
  vtkRenderer* renderer = view.Renderer;
  renderer->AutomaticLightCreationOff();
  voxelgi_test::AddQuad(renderer, { -6, 0, -6 }, { -6, 0, 6 }, { 6, 0, -6 }, 0.8, 0.8, 0.8);
  vtkNew<vtkPolyDataMapper> mapper;
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkGlyph3D> glyphs;
  if (polygons)
  {
    sphere->SetRadius(radius);
    sphere->SetThetaResolution(16);
    sphere->SetPhiResolution(12);
    glyphs->SetInputData(cloud);
    glyphs->SetSourceConnection(sphere->GetOutputPort());
    glyphs->ScalingOff();
    mapper->SetInputConnection(glyphs->GetOutputPort());
  }
  else
  {
    mapper->SetInputData(cloud);
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.9, 0.4, 0.2);
  actor->GetProperty()->SetRenderPointsAsSpheres(!polygons);
  actor->GetProperty()->SetPointSize(PointSize);
  renderer->AddActor(actor);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(-1.0, 10.0, 2.0);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(sun);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(Eye.x, Eye.y, Eye.z);
  camera->SetFocalPoint(Centre.x, Centre.y, Centre.z);
  camera->SetViewAngle(30.0);
  renderer->ResetCameraClippingRange();
  view.Window->Render();
  vtkNew<vtkImageData> albedo;
  vtkNew<vtkFloatArray> indirect;
  if (!view.GI->GetGIActive() ||
    !view.GI->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, albedo) ||
    !view.GI->GetFloatImage(vtkVoxelGIPass::IMAGE_INDIRECT, indirect))
  {
    return false;
  }
  vtkDataArray* values = albedo->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    double p[3];
    albedo->GetPoint(i, p);
    m.Occupied += (p[1] > 0.3 && values->GetComponent(i, 3) > 0.0) ? 1 : 0;
  }
  // The floor below and in front of the cloud: the lower part of the image.
  m.FloorAO = voxelgi_test::MeanOver(indirect, Size, 40, 10, 160, 50, 3);
  return true;
}
}

int TestVoxelImposters(int, char*[])
{
  vtkSmartPointer<vtkPolyData> cloud = Cloud();
  // The sprites' world radius: half the point size in pixels, a pixel being the view's
  // height at the cloud's distance over the image's height.
  const double distance = glm::length(Eye - Centre);
  const double radius = 0.5 * PointSize *
    (2.0 * distance * std::tan(vtkMath::RadiansFromDegrees(15.0))) / Size;
  Measured sprites, spheres;
  VOXELGI_CHECK(Measure(cloud, false, radius, sprites), "GI did not run with the sprites");
  VOXELGI_CHECK(Measure(cloud, true, radius, spheres), "GI did not run with the polygons");
  std::cout << "sphere radius " << radius << ": occupied voxels " << sprites.Occupied
            << " (sprites) against " << spheres.Occupied << " (polygons); floor AO "
            << sprites.FloorAO << " against " << spheres.FloorAO << std::endl;
  VOXELGI_CHECK(spheres.Occupied > 100 && spheres.FloorAO > 0.01, "nothing measured");
  bool ok = voxelgi_test::Within("occupancy of sprites against polygons",
    std::abs(static_cast<double>(sprites.Occupied) / spheres.Occupied - 1.0), 0.05, 0.05);
  ok = voxelgi_test::Within("floor AO of sprites against polygons",
         std::abs(sprites.FloorAO / spheres.FloorAO - 1.0), 0.05, 0.05) &&
    ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
