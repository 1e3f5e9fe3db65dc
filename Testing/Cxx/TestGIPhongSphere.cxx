// VTK's specular coefficient is the peak of an unnormalized Blinn-Phong lobe, not a
// reflectance: a dark green sphere with vedo's "glossy" lighting (specular 0.9, power 90) in
// a white corner under one light must stay dark green with GI, as VTK shows it, not reflect
// 90 % of the bright walls. Over the sphere's middle, the green excess (G - R) of the GI image
// keeps at least 80 % of plain VTK's, and its brightness rises by less than 0.1.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cstdlib>

int TestGIPhongSphere(int, char*[])
{
  vtkNew<vtkRenderer> renderer;
  using glm::dvec3;
  voxelgi_test::AddQuad(renderer, dvec3(-2, 0, -2), dvec3(-2, 0, 2), dvec3(2, 0, -2), 0.8, 0.8, 0.8);
  voxelgi_test::AddQuad(renderer, dvec3(-2, 0, -2), dvec3(2, 0, -2), dvec3(-2, 3, -2), 0.8, 0.8, 0.8);
  voxelgi_test::AddQuad(renderer, dvec3(-2, 0, -2), dvec3(-2, 3, -2), dvec3(-2, 0, 2), 0.8, 0.8, 0.8);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.0, 0.8, 0.0);
  sphere->SetRadius(0.8);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  vtkActor* ball = vtkVoxelGIScenes::AddSource(renderer, sphere, 0.1, 0.35, 0.1);
  ball->GetProperty()->SetSpecular(0.9);
  ball->GetProperty()->SetSpecularPower(90.0);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(1.5, 3.0, 2.5);
  light->SetFocalPoint(0.0, 0.5, 0.0);
  renderer->AddLight(light);

  voxelgi_test::GIWindow view(renderer);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(1.0, 1.5, 5.0);
  camera->SetFocalPoint(0.0, 0.8, 0.0);
  renderer->ResetCameraClippingRange();

  // The sphere's middle, away from the highlight (upper right).
  auto measure = [&](vtkFloatArray* rgba, double& excess, double& brightness) {
    const double r = voxelgi_test::MeanOver(rgba, 200, 85, 75, 100, 90, 0);
    const double g = voxelgi_test::MeanOver(rgba, 200, 85, 75, 100, 90, 1);
    const double b = voxelgi_test::MeanOver(rgba, 200, 85, 75, 100, 90, 2);
    excess = g - r;
    brightness = (r + g + b) / 3.0;
  };
  gi->SetEnabled(false);
  window->Render();
  vtkNew<vtkFloatArray> plain;
  window->GetRGBAPixelData(0, 0, 199, 199, 0, plain);
  gi->SetEnabled(true);
  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
  vtkNew<vtkFloatArray> composite;
  VOXELGI_CHECK(gi->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, composite), "no image");
  double plainExcess, plainBrightness, giExcess, giBrightness;
  measure(plain, plainExcess, plainBrightness);
  measure(composite, giExcess, giBrightness);
  std::cout << "sphere middle: green excess " << giExcess << " (plain VTK " << plainExcess
            << "), brightness " << giBrightness << " (plain VTK " << plainBrightness << ")"
            << std::endl;
  VOXELGI_CHECK(plainExcess > 0.05, "the test sees no green sphere");
  VOXELGI_CHECK(giExcess >= 0.8 * plainExcess, "GI washes the green out");
  VOXELGI_CHECK(giBrightness < plainBrightness + 0.1, "GI brightens the glossy sphere");
  return EXIT_SUCCESS;
}
