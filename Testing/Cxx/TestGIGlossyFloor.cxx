// Glossy specular reflection: a shiny grey floor (Specular 1, SpecularPower 60) under a red
// block lit by a directional light. The specular cone must reflect the red block in the floor
// in front of it: red clearly above green in the indirect image there, not elsewhere, and
// the cone's own share above zero and below what the lobe holds (8/68 of the block's light).
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cstdlib>

int TestGIGlossyFloor(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  using glm::dvec3;
  vtkActor* floor =
    voxelgi_test::AddQuad(renderer, dvec3(-3, 0, -3), dvec3(-3, 0, 3), dvec3(3, 0, -3), 0.3, 0.3, 0.3);
  floor->GetProperty()->SetSpecular(1.0);
  floor->GetProperty()->SetSpecularPower(60.0);
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(-1.0, 1.0, 0.0, 2.0, -1.5, -0.5);
  vtkVoxelGIScenes::AddSource(renderer, cube, 0.9, 0.1, 0.1);

  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(1.0, 3.0, 2.0);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(sun);

  voxelgi_test::GIWindow view(renderer);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 1.2, 6.0);
  camera->SetFocalPoint(0.0, 0.5, -1.0);
  camera->SetViewUp(0, 1, 0);
  renderer->ResetCameraClippingRange();
  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
  VOXELGI_CHECK(voxelgi_test::AllFinite(gi), "non-finite values");

  vtkNew<vtkFloatArray> indirect;
  VOXELGI_CHECK(gi->GetFloatImage(vtkVoxelGIPass::IMAGE_INDIRECT, indirect), "no indirect image");
  // floor just in front of the block (image centre, below it) and far to the side
  const double red = voxelgi_test::MeanOver(indirect, 200, 90, 60, 110, 75, 0);
  const double green = voxelgi_test::MeanOver(indirect, 200, 90, 60, 110, 75, 1);
  const double sideRed = voxelgi_test::MeanOver(indirect, 200, 5, 20, 20, 35, 0);
  std::cout << "floor in front of the block: indirect (r, g) = (" << red << ", " << green
            << "); far side r = " << sideRed << std::endl;
  VOXELGI_CHECK(red > 2.0 * green, "no red reflection of the block in the floor");
  VOXELGI_CHECK(red > 2.0 * sideRed, "the reflection is not localized");
  // The reflection's own share: what the specular cone adds to the diffuse bleeding. VTK's
  // highlight of coefficient 1 and power 60 reflects 8 / 68 of the light around its lobe.
  gi->SpecularConeOff();
  window->Render();
  vtkNew<vtkFloatArray> diffuseOnly;
  gi->GetFloatImage(vtkVoxelGIPass::IMAGE_INDIRECT, diffuseOnly);
  const double bleeding = voxelgi_test::MeanOver(diffuseOnly, 200, 90, 60, 110, 75, 0);
  std::cout << "specular share of the red there: " << red - bleeding << std::endl;
  // The block's lit face is at most about 0.48 (albedo 0.9 under the sun): the lobe's share
  // of it is at most 0.056 (taking ks as a reflectance gave 68/8 times the share measured).
  VOXELGI_CHECK(red - bleeding > 0.005, "the specular cone reflects nothing");
  VOXELGI_CHECK(red - bleeding < 0.056, "the specular cone reflects more than the lobe holds");
  gi->SpecularConeOn();
  window->Render();
  return voxelgi_test::ImageMatches(argc, argv, window);
}
