// Points drawn as spheres (RenderPointsAsSpheres) and lines drawn as tubes (RenderLinesAsTubes)
// against the same shapes as polygons: a cloud of 150 points of 10 pixels, and nine lines of 10
// pixels, over a floor under a sun, and the same points glyphed with polygonal spheres, the
// same lines swept into polygonal tubes, of the radius the imposters show (half the point size
// or line width in pixels at the shapes' centre's distance from the camera: VTK's imposters are
// that many pixels across). Their voxel occupancy above the floor and the ambient occlusion of
// the floor below them agree within 5 %.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3D.h"
#include "vtkTubeFilter.h"
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

/// Nine lines along x, 3 long, on a 3 x 3 grid across y and z around Centre.
vtkSmartPointer<vtkPolyData> Lines()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (int j = -1; j <= 1; ++j)
  {
    for (int k = -1; k <= 1; ++k)
    {
      lines->InsertNextCell(10);
      for (int i = 0; i < 10; ++i)
      {
        lines->InsertCellPoint(points->InsertNextPoint(-1.5 + i / 3.0, Centre.y + j, k));
      }
    }
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->SetPoints(points);
  result->SetLines(lines);
  return result;
}

/// Render `shapes` (points, or lines with `tubes`) over the floor as imposters or as polygonal
/// spheres or tubes of `radius`.
bool Measure(vtkPolyData* shapes, bool tubes, bool polygons, double radius, Measured& m)
{
  voxelgi_test::GIWindow view(nullptr, 64, Size, 0);
  vtkRenderer* renderer = view.Renderer;
  renderer->AutomaticLightCreationOff();
  voxelgi_test::AddQuad(renderer, { -6, 0, -6 }, { -6, 0, 6 }, { 6, 0, -6 }, 0.8, 0.8, 0.8);
  vtkNew<vtkPolyDataMapper> mapper;
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkGlyph3D> glyphs;
  vtkNew<vtkTubeFilter> swept;
  if (polygons && tubes)
  {
    swept->SetInputData(shapes);
    swept->SetRadius(radius);
    swept->SetNumberOfSides(16);
    swept->CappingOn();
    mapper->SetInputConnection(swept->GetOutputPort());
  }
  else if (polygons)
  {
    sphere->SetRadius(radius);
    sphere->SetThetaResolution(16);
    sphere->SetPhiResolution(12);
    glyphs->SetInputData(shapes);
    glyphs->SetSourceConnection(sphere->GetOutputPort());
    glyphs->ScalingOff();
    mapper->SetInputConnection(glyphs->GetOutputPort());
  }
  else
  {
    mapper->SetInputData(shapes);
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.9, 0.4, 0.2);
  actor->GetProperty()->SetRenderPointsAsSpheres(!polygons && !tubes);
  actor->GetProperty()->SetRenderLinesAsTubes(!polygons && tubes);
  actor->GetProperty()->SetPointSize(PointSize);
  actor->GetProperty()->SetLineWidth(PointSize);
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
  // The floor below and in front of the shapes: the lower part of the image.
  m.FloorAO = voxelgi_test::MeanOver(indirect, Size, 40, 10, 160, 50, 3);
  return true;
}

/// The imposters of `shapes` against the same shapes as polygons.
bool Compare(vtkPolyData* shapes, bool tubes)
{
  // The imposters' world radius: half their size in pixels, a pixel being the view's height
  // at the shapes' distance over the image's height.
  const double distance = glm::length(Eye - Centre);
  const double radius = 0.5 * PointSize *
    (2.0 * distance * std::tan(vtkMath::RadiansFromDegrees(15.0))) / Size;
  const char* what = tubes ? "tubes" : "spheres";
  Measured imposters, polygons;
  if (!Measure(shapes, tubes, false, radius, imposters) ||
    !Measure(shapes, tubes, true, radius, polygons))
  {
    std::cerr << what << ": GI did not run" << std::endl;
    return false;
  }
  std::cout << what << " of radius " << radius << ": occupied voxels " << imposters.Occupied
            << " (imposters) against " << polygons.Occupied << " (polygons); floor AO "
            << imposters.FloorAO << " against " << polygons.FloorAO << std::endl;
  if (polygons.Occupied <= 100 || polygons.FloorAO <= 0.01)
  {
    std::cerr << what << ": nothing measured" << std::endl;
    return false;
  }
  bool ok = voxelgi_test::Within(std::string("occupancy of imposter ") + what + " against polygons",
    std::abs(static_cast<double>(imposters.Occupied) / polygons.Occupied - 1.0), 0.05, 0.05);
  ok = voxelgi_test::Within(std::string("floor AO of imposter ") + what + " against polygons",
         std::abs(imposters.FloorAO / polygons.FloorAO - 1.0), 0.05, 0.05) &&
    ok;
  return ok;
}
}

int TestVoxelImposters(int, char*[])
{
  const bool spheres = Compare(Cloud(), false);
  const bool tubes = Compare(Lines(), true);
  return spheres && tubes ? EXIT_SUCCESS : EXIT_FAILURE;
}
