// VTK's automatic headlight lights the voxels (it moves with the camera) and its shadows are
// not cone traced; a sphere and a block on a floor, compared with the baseline.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkCamera.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cstdlib>

int TestGIHeadlight(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  voxelgi_test::AddSphereAndBlockOnFloor(renderer);

  voxelgi_test::GIWindow view(renderer);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
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
