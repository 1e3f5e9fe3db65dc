// Emissive-only lighting: no vtkLight (automatic light creation off), one emissive quad over
// a white floor in front of a white wall. Only GI lights the room: the floor voxels under the
// quad must be lit (radiance volume) and far more than the far corner, and the image matches.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkNew.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cstdlib>

int TestGIEmissiveOnly(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  renderer->AutomaticLightCreationOff();
  using glm::dvec3;
  // floor (normal +y) and back wall (normal +z)
  voxelgi_test::AddQuad(renderer, dvec3(0, 0, 0), dvec3(0, 0, 4), dvec3(4, 0, 0), 0.8, 0.8, 0.8);
  voxelgi_test::AddQuad(renderer, dvec3(0, 0, 0), dvec3(4, 0, 0), dvec3(0, 3, 0), 0.8, 0.8, 0.8);
  // emissive panel facing down, above the left half of the floor
  vtkActor* panel = voxelgi_test::AddQuad(
    renderer, dvec3(0.5, 1.2, 0.5), dvec3(1.7, 1.2, 0.5), dvec3(0.5, 1.2, 1.7), 1.0, 0.9, 0.7);
  panel->GetProperty()->SetAmbient(1.0);
  panel->GetProperty()->SetAmbientColor(1.0, 0.9, 0.7);
  vtkVoxelGIPass::SetPropEmission(panel, 3.0, 2.7, 2.1);

  voxelgi_test::GIWindow view(renderer);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(2.5, 2.5, 7.0);
  camera->SetFocalPoint(1.6, 0.7, 1.2);
  camera->SetViewUp(0, 1, 0);
  renderer->ResetCameraClippingRange();
  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
  VOXELGI_CHECK(voxelgi_test::AllFinite(gi), "non-finite values");

  vtkNew<vtkImageData> radiance;
  VOXELGI_CHECK(gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_RADIANCE, radiance), "no radiance");
  vtkDataArray* values = radiance->GetPointData()->GetScalars();
  const double under = values->GetComponent(radiance->FindPoint(1.1, 0.01, 1.1), 0);
  const double far = values->GetComponent(radiance->FindPoint(3.8, 0.01, 3.8), 0);
  std::cout << "floor radiance (red): under the panel " << under << ", far corner " << far
            << std::endl;
  VOXELGI_CHECK(under > 0.1, "the emissive panel does not light the floor");
  VOXELGI_CHECK(under > 5.0 * far, "indirect light does not fall off away from the panel");
  return voxelgi_test::ImageMatches(argc, argv, window);
}
