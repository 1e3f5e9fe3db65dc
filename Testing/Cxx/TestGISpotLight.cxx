// A spot light (cone 25 degrees, exponent 2) over a floor with a block: voxels inside the
// cone are lit following VTK's spot model, voxels outside it get no direct light (bounces
// off), and the image matches its baseline.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cstdlib>

int TestGISpotLight(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  using glm::dvec3;
  voxelgi_test::AddQuad(renderer, dvec3(-3, 0, -3), dvec3(-3, 0, 3), dvec3(3, 0, -3), 0.8, 0.8, 0.8);
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(-0.4, 0.4, 0.0, 0.8, -0.4, 0.4);
  vtkVoxelGIScenes::AddSource(renderer, cube, 0.2, 0.4, 0.9);

  vtkNew<vtkLight> spot;
  spot->SetLightTypeToSceneLight();
  spot->SetPositional(true);
  spot->SetPosition(0.0, 3.0, 0.0);
  spot->SetFocalPoint(0.0, 0.0, 0.0);
  spot->SetConeAngle(25.0);
  spot->SetExponent(2.0);
  renderer->AddLight(spot);

  voxelgi_test::GIWindow view(renderer);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  gi->SetBounces(0);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 4.0, 6.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0, 1, 0);
  renderer->ResetCameraClippingRange();
  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
  VOXELGI_CHECK(voxelgi_test::AllFinite(gi), "non-finite values");

  vtkNew<vtkImageData> radiance;
  VOXELGI_CHECK(gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_RADIANCE, radiance), "no radiance");
  vtkDataArray* values = radiance->GetPointData()->GetScalars();
  // The cone reaches the floor at radius 3 tan(25 deg) = 1.40.
  // VTK's spot model at the voxel centre c: attenuation cos(angle)^exponent inside the cone,
  // times Lambert (the floor's normal is +y); albedo 0.8.
  double c[3];
  const vtkIdType insideId = radiance->FindPoint(1.0, 0.01, 0.0);
  radiance->GetPoint(insideId, c);
  const double d = std::sqrt(c[0] * c[0] + (3.0 - c[1]) * (3.0 - c[1]) + c[2] * c[2]);
  const double cosAngle = (3.0 - c[1]) / d;
  const double expected = 0.8 * cosAngle * std::pow(cosAngle, 2.0);
  const double inside = values->GetComponent(insideId, 0);
  const double outside = values->GetComponent(radiance->FindPoint(2.0, 0.01, 0.0), 0);
  std::cout << "floor radiance inside the cone " << inside << " (VTK's spot model " << expected
            << "), outside " << outside << std::endl;
  VOXELGI_CHECK(std::abs(inside - expected) < 0.01 * expected, "spot attenuation differs");
  VOXELGI_CHECK(outside == 0.0, "light outside the spot cone");
  return voxelgi_test::ImageMatches(argc, argv, window);
}
