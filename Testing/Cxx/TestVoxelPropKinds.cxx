// Actor classes that draw through an internal actor are voxelized with their colour and
// transform: a red sphere (radius 0.3) moved to (1, 0.5, 0) by its actor's position, over a grey
// floor, as a vtkFollower ("follower"), a vtkLODActor ("lod") or a vtkQuadricLODActor
// ("quadric", in a window with an interactor, which VTK's class needs), or as an unstructured
// grid drawn by a vtkDataSetMapper ("dataset"); case "assembly": the sphere as a plain actor
// next to a nested vtkAssembly with a transform (left to VTK, which bumps its parts' times at
// every render): an unchanged frame only presents, moving the assembly traces again; case
// "edges": the sphere as a plain actor with green edges drawn as tubes and green vertices as
// spheres (as VTK's TestCompositePolyDataMapper2Vertices: VTK 9.1's unlit shaders do not compile
// for it, and the pass's own renderers were unlit; and the voxels of a surface with edges were
// black): the voxels keep the surface's red; case "composite": the same drawn by a
// vtkCompositePolyDataMapper2 from a multiblock, as that VTK test; case "tubes": the same sphere
// as a plain actor next to a line drawn as a tube (RenderLinesAsTubes), whose voxelization
// shader once failed to compile and crashed, is voxelized as the cylinder it shows, in its
// colour, and not named in the notice; case "spheres": next to a point cloud drawn as spheres
// (RenderPointsAsSpheres, as vedo's Points), voxelized as the spheres it shows, in its colour;
// case "widget": next to an implicit plane widget (a cutter's), left to VTK: an unchanged frame
// only presents, moving the plane draws again. The voxel at the sphere's side holds its colour;
// the voxel where the sphere would be without its position is empty.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkAppendFilter.h"
#include "vtkAssembly.h"
#include "vtkCamera.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkDataSetMapper.h"
#include "vtkFollower.h"
#include "vtkImageData.h"
#include "vtkImplicitPlaneRepresentation.h"
#include "vtkImplicitPlaneWidget2.h"
#include "vtkLODActor.h"
#include "vtkLight.h"
#include "vtkLineSource.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkQuadricLODActor.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <string>

int TestVoxelPropKinds(int argc, char* argv[])
{
  const std::string which = argc > 1 ? argv[1] : "follower";
  vtkNew<vtkRenderer> renderer;
  using glm::dvec3;
  voxelgi_test::AddQuad(renderer, dvec3(-2, 0, -2), dvec3(-2, 0, 2), dvec3(2, 0, -2), 0.5, 0.5, 0.5);
  vtkNew<vtkSphereSource> ball;
  ball->SetRadius(0.3);
  ball->SetThetaResolution(24);
  ball->SetPhiResolution(24);
  vtkSmartPointer<vtkMapper> mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  if (which == "dataset")
  {
    vtkNew<vtkAppendFilter> grid; // the sphere's polygons as an unstructured grid
    grid->SetInputConnection(ball->GetOutputPort());
    mapper = vtkSmartPointer<vtkDataSetMapper>::New();
    mapper->SetInputConnection(grid->GetOutputPort());
  }
  else if (which == "composite")
  {
    // VTK's TestCompositePolyDataMapper2Vertices: blocks drawn with their vertices as spheres
    ball->Update();
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetNumberOfBlocks(1);
    blocks->SetBlock(0, ball->GetOutput());
    mapper = vtkSmartPointer<vtkCompositePolyDataMapper2>::New();
    mapper->SetInputDataObject(blocks);
  }
  else
  {
    mapper->SetInputConnection(ball->GetOutputPort());
  }
  vtkSmartPointer<vtkActor> actor;
  if (which == "follower")
  {
    auto follower = vtkSmartPointer<vtkFollower>::New();
    follower->SetCamera(renderer->GetActiveCamera());
    actor = follower;
  }
  else if (which == "lod")
  {
    actor = vtkSmartPointer<vtkLODActor>::New();
  }
  else if (which == "quadric")
  {
    actor = vtkSmartPointer<vtkQuadricLODActor>::New();
  }
  else if (which == "dataset" || which == "assembly" || which == "widget")
  {
    actor = vtkSmartPointer<vtkActor>::New();
  }
  else if (which == "edges" || which == "composite")
  {
    actor = vtkSmartPointer<vtkActor>::New();
    vtkProperty* property = actor->GetProperty();
    property->EdgeVisibilityOn();
    property->RenderLinesAsTubesOn();
    property->SetLineWidth(4.0);
    property->SetEdgeColor(0.1, 0.9, 0.1); // the voxels take the surface's colour
    property->VertexVisibilityOn();
    property->RenderPointsAsSpheresOn();
    property->SetPointSize(6.0);
    property->SetVertexColor(0.1, 0.9, 0.1);
  }
  else if (which == "spheres")
  {
    actor = vtkSmartPointer<vtkActor>::New();
    vtkNew<vtkPointSource> cloud;
    cloud->SetCenter(-1.0, 0.8, 0.0);
    cloud->SetRadius(0.3);
    cloud->SetNumberOfPoints(200);
    vtkProperty* points =
      vtkVoxelGIScenes::AddSource(renderer, cloud, 0.2, 0.3, 0.9)->GetProperty();
    points->SetRenderPointsAsSpheres(true);
    points->SetPointSize(8.0);
  }
  else
  {
    actor = vtkSmartPointer<vtkActor>::New();
    vtkNew<vtkLineSource> line;
    line->SetPoint1(-1.5, 0.4, -1.0);
    line->SetPoint2(1.5, 0.4, -1.0);
    line->SetResolution(8);
    vtkProperty* tube = vtkVoxelGIScenes::AddSource(renderer, line, 0.2, 0.3, 0.9)->GetProperty();
    tube->SetRenderLinesAsTubes(true);
    tube->SetLineWidth(6.0);
  }
  actor->SetMapper(mapper);
  actor->SetPosition(1.0, 0.5, 0.0);
  actor->GetProperty()->SetColor(0.9, 0.1, 0.1);
  renderer->AddActor(actor);
  vtkNew<vtkAssembly> outer;
  if (which == "assembly")
  {
    vtkNew<vtkCubeSource> cube;
    vtkNew<vtkPolyDataMapper> cubeMapper;
    cubeMapper->SetInputConnection(cube->GetOutputPort());
    vtkNew<vtkActor> block;
    block->SetMapper(cubeMapper);
    block->SetScale(0.4);
    vtkNew<vtkAssembly> inner;
    inner->AddPart(block);
    inner->SetPosition(0.0, 0.3, 0.0);
    outer->AddPart(inner);
    outer->SetPosition(-1.0, 0.0, 0.5);
    renderer->AddActor(outer);
  }
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(1.0, 4.0, 3.0);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(light);

  voxelgi_test::GIWindow view(renderer, 64, 100);
  voxelgi_test::Messages log(view.GI);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(view.Window);
  vtkNew<vtkImplicitPlaneRepresentation> plane;
  vtkNew<vtkImplicitPlaneWidget2> widget;
  if (which == "widget")
  {
    double box[6] = { -1.5, 1.5, 0.0, 1.0, -1.5, 1.5 };
    plane->PlaceWidget(box);
    plane->SetNormal(1.0, 0.0, 0.0);
    widget->SetInteractor(interactor);
    widget->SetRepresentation(plane);
    widget->On();
  }
  renderer->GetActiveCamera()->SetPosition(2.0, 3.0, 5.0);
  renderer->ResetCamera();
  view.Window->Render();
  view.Window->Render();
  VOXELGI_CHECK(view.GI->GetGIActive(), which << ": GI did not run");

  vtkNew<vtkImageData> albedo;
  VOXELGI_CHECK(view.GI->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, albedo), "no albedo");
  auto voxel = [&](double x, double y, double z) {
    double p[3] = { x, y, z };
    return albedo->GetPointData()->GetScalars()->GetTuple4(albedo->FindPoint(p));
  };
  const double* side = voxel(1.29, 0.5, 0.0);
  std::cout << which << ": voxel at the sphere's side " << side[0] << " " << side[1] << " "
            << side[2] << " " << side[3] << std::endl;
  VOXELGI_CHECK(side[3] == 255, which << ": the sphere is not voxelized at its position");
  VOXELGI_CHECK(side[0] > 200 && side[1] < 60 && side[2] < 60, which << ": not the sphere's red");
  const double* unmoved = voxel(0.29, 0.5, 0.0);
  VOXELGI_CHECK(unmoved[3] == 0, which << ": voxels where the sphere is without its position");
  if (which == "tubes")
  {
    // The tube's shell in its blue around the line (hollow: its axis may stay empty), and
    // nothing said.
    int shell = 0;
    for (double y = 0.2; y <= 0.6; y += 0.02)
    {
      for (double z = -1.2; z <= -0.8; z += 0.02)
      {
        const double* v = voxel(0.0, y, z);
        shell += v[3] == 255 && v[2] > 200 && v[0] < 80 ? 1 : 0;
      }
    }
    std::cout << which << ": " << shell << " samples of the tube's cross-section occupied in blue; "
              << "said: " << log.Text << std::endl;
    VOXELGI_CHECK(shell > 0, which << ": the tube is not voxelized in its colour");
    VOXELGI_CHECK(!log.Has("tubes"), which << ": the tube is named in the notice");
  }
  else if (which == "spheres")
  {
    // The cloud's middle, 0.3 across, is full of spheres.
    const double* cloud = voxel(-1.0, 0.8, 0.0);
    std::cout << which << ": voxel in the cloud " << cloud[0] << " " << cloud[1] << " "
              << cloud[2] << " " << cloud[3] << "; said: " << log.Text << std::endl;
    VOXELGI_CHECK(log.Text.empty(), which << ": " << log.Text);
    VOXELGI_CHECK(cloud[3] == 255 && cloud[2] > 150 && cloud[0] < 100,
      which << ": the spheres are not voxelized in their blue");
  }
  else
  {
    VOXELGI_CHECK(log.Text.empty() || which == "assembly" || which == "widget",
      which << ": " << log.Text);
  }
  if (which == "assembly" || which == "widget")
  {
    view.Window->Render();
    const std::string unchanged = voxelgi_test::StagesRan(view.GI);
    if (which == "widget")
    {
      plane->SetOrigin(0.3, 0.5, 0.0);
    }
    else
    {
      outer->SetPosition(-1.0, 0.0, 0.2);
    }
    view.Window->Render();
    const std::string moved = voxelgi_test::StagesRan(view.GI);
    std::cout << "unchanged frame: " << unchanged << "; moved: " << moved << std::endl;
    VOXELGI_CHECK(unchanged == "Scan,Present", which << ": an unchanged frame traced again");
    VOXELGI_CHECK(moved.find("GBuffer") != std::string::npos, which << ": moved, not drawn again");
  }
  return EXIT_SUCCESS;
}
