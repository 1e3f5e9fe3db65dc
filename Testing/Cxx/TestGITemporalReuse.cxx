// Temporal reuse must not smear. A box moves without being revoxelized (UpdatePolicy
// OnDemand, so only the G-buffer sees it move: the place it leaves shows another surface),
// first under a still camera, then while the camera moves along a path (orbit, rise and
// dolly). Every frame of a pass with TemporalReuse is compared with the same frame of a pass
// that traces every pixel (a second window with the same scene). Under the still camera the
// two must agree (a trail behind the box would differ by its colour); along the path the
// differences are resampling (reused results come from last frame's pixels, up to a quarter
// voxel away) and must stay small. Every such frame must really have reused, and a change of
// the lights must trace everything again (then the two agree exactly).
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>

namespace
{
struct View : voxelgi_test::GIWindow
{
  vtkActor* Box = nullptr;

  explicit View(bool reuse)
    : GIWindow(nullptr, 32, 200, 0)
  {
    vtkVoxelGIScenes::AddCornellBox(this->Renderer);
    vtkNew<vtkCubeSource> box;
    box->SetBounds(3.4, 4.2, 0.0, 0.8, 3.6, 4.4);
    this->Box = vtkVoxelGIScenes::AddSource(this->Renderer, box, 0.9, 0.7, 0.2);
    this->GI->SetTemporalReuse(reuse);
    this->GI->SetUpdatePolicyToOnDemand();
  }

  void Step(int frame, bool moveCamera)
  {
    if (moveCamera)
    {
      vtkCamera* camera = this->Renderer->GetActiveCamera();
      camera->Azimuth(1.5);
      camera->Elevation(0.5);
      camera->Dolly(1.01);
      camera->OrthogonalizeViewUp();
      this->Renderer->ResetCameraClippingRange();
    }
    this->Box->SetPosition(-0.05 * frame, 0.0, 0.0);
    this->Window->Render();
  }
};

// Largest and mean absolute difference of the two composites (rgb), and the fraction of
// pixels that differ by more than 0.02.
void Compare(vtkVoxelGIPass* a, vtkVoxelGIPass* b, double& largest, double& mean, double& over)
{
  vtkNew<vtkFloatArray> ia, ib;
  a->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, ia);
  b->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, ib);
  const voxelgi_test::ImageDifference difference = voxelgi_test::Differences(ia, ib, 0.02);
  largest = difference.Largest;
  mean = difference.Mean;
  over = difference.Over;
}
}

int TestGITemporalReuse(int, char*[])
{
  View reused(true);
  View traced(false);
  reused.Window->Render();
  traced.Window->Render();
  VOXELGI_CHECK(reused.GI->GetGIActive() && traced.GI->GetGIActive(), "GI did not run");
  VOXELGI_CHECK(!reused.GI->GetTraceReused(), "the first frame reused a frame before it");

  // The largest difference, the mean difference and the pixels over 0.02, worst per phase.
  double worst[2][3] = {};
  for (int frame = 1; frame <= 24; ++frame)
  {
    const bool moveCamera = frame > 8;
    reused.Step(frame, moveCamera);
    traced.Step(frame, moveCamera);
    VOXELGI_CHECK(reused.GI->GetTraceReused(), "frame " << frame << " traced everything");
    VOXELGI_CHECK(!traced.GI->GetTraceReused(), "frame " << frame << " reused with reuse off");
    VOXELGI_CHECK(voxelgi_test::AllFinite(reused.GI), "frame " << frame << " not finite");
    double d[3];
    Compare(reused.GI, traced.GI, d[0], d[1], d[2]);
    std::cout << "frame " << frame << (moveCamera ? " (camera moving)" : " (camera still)")
              << ": largest difference " << d[0] << ", mean " << d[1]
              << ", pixels over 0.02: " << 100.0 * d[2] << " %" << std::endl;
    for (int m = 0; m < 3; ++m)
    {
      worst[moveCamera][m] = std::max(worst[moveCamera][m], d[m]);
    }
  }
  VOXELGI_CHECK(worst[0][0] < 0.01, "the box left a trail: largest difference " << worst[0][0]);
  // Measured (llvmpipe): mean <= 0.0014, up to 0.56 % of the pixels over 0.02, largest 0.24
  // (results carried for up to five frames; at three: 0.0013, 0.50 %, 0.25),
  // where the traced light varies sharply within a voxel of this coarse 32^3 grid (a voxel
  // about five pixels wide). The scene light's shadows come from its shadow map and are looked
  // up afresh in reused tiles (resampled, their sharp edges gave up to 0.72); the composite
  // gathers the indirect light over the four cone turns of each 2 x 2 block (before, one
  // fixed cone set: largest 0.50, 6.8 % of the pixels).
  VOXELGI_CHECK(worst[1][1] < 0.0015, "reuse moved the image: mean difference " << worst[1][1]);
  VOXELGI_CHECK(worst[1][2] < 0.01, "reuse changed " << 100.0 * worst[1][2] << " % of pixels");
  VOXELGI_CHECK(worst[1][0] < 0.3, "a reused pixel is far from its traced value: " << worst[1][0]);

  // A change of the lights relights the voxels: everything is traced again.
  for (View* view : { &reused, &traced })
  {
    vtkLight* light = vtkLight::SafeDownCast(view->Renderer->GetLights()->GetItemAsObject(0));
    light->SetIntensity(0.8 * light->GetIntensity());
    view->Window->Render();
  }
  VOXELGI_CHECK(!reused.GI->GetTraceReused(), "a light change reused the frame before");
  double largest, mean, over;
  Compare(reused.GI, traced.GI, largest, mean, over);
  std::cout << "after a light change: largest difference " << largest << std::endl;
  VOXELGI_CHECK(largest < 1e-5, "a full trace differs from a pass without reuse: " << largest);
  return EXIT_SUCCESS;
}
