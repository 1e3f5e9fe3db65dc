// VTK's automatic headlight lights the voxels (it moves with the camera) and its shadows are
// not cone traced; a sphere and a block on a floor, compared with the baseline.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cstdlib>

int TestGIHeadlight(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  using glm::dvec3;
  voxelgi_test::AddQuad(renderer, dvec3(-3, 0, -3), dvec3(-3, 0, 3), dvec3(3, 0, -3), 0.8, 0.8, 0.8);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(-0.8, 0.8, 0.0);
  sphere->SetRadius(0.8);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  vtkVoxelGIScenes::AddSource(renderer, sphere, 0.9, 0.6, 0.1);
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(0.4, 1.6, 0.0, 1.2, -0.8, 0.4);
  vtkVoxelGIScenes::AddSource(renderer, cube, 0.2, 0.5, 0.9);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(200, 200);
  window->AddRenderer(renderer);
  vtkNew<vtkVoxelGIPass> gi;
  gi->SetVoxelResolution(64);
  renderer->SetPass(gi);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(1.0, 3.0, 5.5);
  camera->SetFocalPoint(0.0, 0.4, 0.0);
  camera->SetViewUp(0, 1, 0);
  renderer->ResetCameraClippingRange();
  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
  VOXELGI_CHECK(renderer->GetLights()->GetNumberOfItems() == 1, "no automatic headlight");
  VOXELGI_CHECK(voxelgi_test::AllFinite(gi), "non-finite values");
  return voxelgi_test::ImageMatches(argc, argv, window);
}
