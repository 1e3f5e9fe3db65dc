// Shapes of real VTK programs, each with its stage expectations, the numbers a user asks
// about printed, and a baseline image.
//
//   viewports  four viewports on one Cornell box: the first pass owns the voxel grid, the
//              other three share it (SetVoxelSource). They allocate no voxel volume and run no
//              voxel stage, their images equal those of passes with grids of their own, an
//              unchanged frame only presents, a moved block retraces every viewport, and a
//              camera move in one viewport traces that viewport alone.
//   headlight  an orbit under VTK's automatic headlight against the same orbit under a scene
//              light: the headlight's voxel light is kept while it turns less than
//              CameraLightTurn (one relight over a 60 degree orbit, whose
//              headlight turns by 54 degrees), every frame reuses the
//              trace; milliseconds per orbit frame of both printed.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkPropCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <string>

namespace
{

using voxelgi_test::StagesRan;

/// Whether any voxel stage (scan to bounce) ran.
bool RanVoxelStage(vtkVoxelGIPass* gi)
{
  for (int stage = vtkVoxelGIPass::STAGE_SCAN; stage <= vtkVoxelGIPass::STAGE_BOUNCE; ++stage)
  {
    if (gi->GetStageRan(stage))
    {
      return true;
    }
  }
  return false;
}

/// Largest channel difference between two RGBA images of the same size.
int LargestDifference(vtkUnsignedCharArray* a, vtkUnsignedCharArray* b)
{
  int largest = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    largest = std::max(largest, std::abs(static_cast<int>(a->GetValue(i)) - b->GetValue(i)));
  }
  return largest;
}

int Viewports(int argc, char* argv[])
{
  constexpr int Size = 320;
  constexpr int Count = 4;
  vtkNew<vtkRenderWindow> window;
  window->SetSize(Size, Size);
  window->SetMultiSamples(0);
  std::array<vtkSmartPointer<vtkRenderer>, Count> renderers;
  std::array<vtkSmartPointer<vtkVoxelGIPass>, Count> passes;
  const double views[Count][2] = { { 0, 0 }, { 15, 0 }, { 0, 15 }, { -15, -8 } };
  for (int i = 0; i < Count; ++i)
  {
    renderers[i] = vtkSmartPointer<vtkRenderer>::New();
    renderers[i]->SetViewport(0.5 * (i % 2), 0.5 * (i / 2), 0.5 * (i % 2) + 0.5, 0.5 * (i / 2) + 0.5);
    if (i == 0)
    {
      vtkVoxelGIScenes::AddCornellBox(renderers[0]);
    }
    else
    {
      // The same props and lights, as a multi-view program shows them.
      vtkPropCollection* props = renderers[0]->GetViewProps();
      props->InitTraversal();
      while (vtkProp* prop = props->GetNextProp())
      {
        renderers[i]->AddViewProp(prop);
      }
      vtkLightCollection* lights = renderers[0]->GetLights();
      lights->InitTraversal();
      while (vtkLight* light = lights->GetNextItem())
      {
        renderers[i]->AddLight(light);
      }
      renderers[i]->GetActiveCamera()->DeepCopy(renderers[0]->GetActiveCamera());
      renderers[i]->GetActiveCamera()->Azimuth(views[i][0]);
      renderers[i]->GetActiveCamera()->Elevation(views[i][1]);
      renderers[i]->ResetCameraClippingRange();
    }
    passes[i] = vtkSmartPointer<vtkVoxelGIPass>::New();
    passes[i]->SetSoftwareProfileToOff();
    passes[i]->SetVoxelResolution(32);
    renderers[i]->SetPass(passes[i]);
    window->AddRenderer(renderers[i]);
  }
  const auto capture = [&window](vtkUnsignedCharArray* pixels) {
    window->GetRGBACharPixelData(0, 0, Size - 1, Size - 1, 0, pixels);
  };
  const auto timedRender = [&window]() {
    vtkNew<vtkTimerLog> timer;
    timer->StartTimer();
    window->Render();
    timer->StopTimer();
    return 1000.0 * timer->GetElapsedTime();
  };
  const auto totalVoxelBytes = [&passes]() {
    unsigned long long bytes = 0;
    for (auto& gi : passes)
    {
      bytes += gi->GetVoxelMemoryBytes();
    }
    return bytes;
  };

  // Every pass with a grid of its own.
  window->Render();
  const double ownFrame = timedRender(); // an unchanged frame, for the printout only
  passes[0]->Invalidate();
  for (auto& gi : passes)
  {
    gi->Invalidate();
  }
  const double ownRebuild = timedRender();
  vtkNew<vtkUnsignedCharArray> own;
  capture(own);
  const unsigned long long ownBytes = totalVoxelBytes();

  // Three share the first's.
  for (int i = 1; i < Count; ++i)
  {
    passes[i]->SetVoxelSource(passes[0]);
  }
  window->Render();
  for (int i = 0; i < Count; ++i)
  {
    VOXELGI_CHECK(passes[i]->GetGIActive(), "viewport " << i << ": GI did not run");
    VOXELGI_CHECK(voxelgi_test::Bounded(passes[i]), "viewport " << i << ": non-finite values");
  }
  vtkNew<vtkUnsignedCharArray> shared;
  capture(shared);
  const unsigned long long sharedBytes = totalVoxelBytes();
  passes[0]->Invalidate();
  const double sharedRebuild = timedRender();
  std::cout << "voxel memory of four viewports: " << ownBytes / (1024 * 1024)
            << " MiB with four grids, " << sharedBytes / (1024 * 1024)
            << " MiB with one shared grid" << std::endl;
  std::cout << "frame rebuilding the voxels: " << ownRebuild << " ms with four grids, "
            << sharedRebuild << " ms with one (unchanged frame " << ownFrame << " ms)"
            << std::endl;
  for (int i = 1; i < Count; ++i)
  {
    VOXELGI_CHECK(passes[i]->GetVoxelMemoryBytes() == 0,
      "viewport " << i << " holds " << passes[i]->GetVoxelMemoryBytes() << " voxel bytes");
    VOXELGI_CHECK(!RanVoxelStage(passes[i]), "viewport " << i << " ran " << StagesRan(passes[i]));
    VOXELGI_CHECK(passes[i]->GetGridResolution() == 32, "viewport " << i << ": no grid");
  }
  VOXELGI_CHECK(4 * sharedBytes == ownBytes, "shared " << sharedBytes << " own " << ownBytes);
  const int difference = LargestDifference(own, shared);
  std::cout << "largest difference to four grids of their own: " << difference << " levels"
            << std::endl;
  VOXELGI_CHECK(difference <= 2, "the shared grid changes the image by " << difference);

  // Nothing changed: every pass presents its last image.
  window->Render();
  VOXELGI_CHECK(StagesRan(passes[0]) == "Scan,Present", "owner ran " << StagesRan(passes[0]));
  for (int i = 1; i < Count; ++i)
  {
    VOXELGI_CHECK(StagesRan(passes[i]) == "Present", "viewport " << i << " ran " << StagesRan(passes[i]));
  }

  // A block moves: the owner revoxelizes, every viewport traces anew (no reuse).
  vtkActor* block = renderers[0]->GetActors()->GetLastActor();
  block->AddPosition(0.0, 0.0, 0.05);
  window->Render();
  VOXELGI_CHECK(passes[0]->GetStageRan(vtkVoxelGIPass::STAGE_LIGHT), "owner ran " << StagesRan(passes[0]));
  for (int i = 1; i < Count; ++i)
  {
    VOXELGI_CHECK(!RanVoxelStage(passes[i]) && passes[i]->GetStageRan(vtkVoxelGIPass::STAGE_CONE_TRACE) &&
        !passes[i]->GetTraceReused(),
      "viewport " << i << " ran " << StagesRan(passes[i]) << ", reused " << passes[i]->GetTraceReused());
  }

  // One viewport's camera moves: it alone traces, reusing its last frame.
  renderers[2]->GetActiveCamera()->Azimuth(2.0);
  window->Render();
  VOXELGI_CHECK(passes[2]->GetTraceReused(), "viewport 2 ran " << StagesRan(passes[2]));
  VOXELGI_CHECK(StagesRan(passes[0]) == "Scan,Present", "owner ran " << StagesRan(passes[0]));
  VOXELGI_CHECK(StagesRan(passes[1]) == "Present", "viewport 1 ran " << StagesRan(passes[1]));
  return voxelgi_test::ImageMatches(argc, argv, window);
}

int Headlight(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  voxelgi_test::AddSphereAndBlockOnFloor(renderer);
  voxelgi_test::GIWindow view(renderer, 64, 200, 0);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  vtkCamera* camera = renderer->GetActiveCamera();

  // 30 frames of 2 degrees; returns the mean frame time and counts the relit frames.
  constexpr int Frames = 30;
  const auto orbit = [&](int& relit, int& reused) {
    camera->SetPosition(1.0, 3.0, 5.5);
    camera->SetFocalPoint(0.0, 0.4, 0.0);
    camera->SetViewUp(0, 1, 0);
    renderer->ResetCameraClippingRange();
    window->Render();
    relit = reused = 0;
    vtkNew<vtkTimerLog> timer;
    timer->StartTimer();
    for (int frame = 0; frame < Frames; ++frame)
    {
      camera->Azimuth(2.0);
      renderer->ResetCameraClippingRange();
      window->Render();
      relit += gi->GetStageRan(vtkVoxelGIPass::STAGE_LIGHT) ? 1 : 0;
      reused += gi->GetTraceReused() ? 1 : 0;
    }
    timer->StopTimer();
    return 1000.0 * timer->GetElapsedTime() / Frames;
  };

  // A scene light where the headlight starts: VTK's automatic headlight goes once one is set.
  vtkNew<vtkLight> sceneLight;
  sceneLight->SetLightTypeToSceneLight();
  sceneLight->SetPosition(1.0, 3.0, 5.5);
  sceneLight->SetFocalPoint(0.0, 0.4, 0.0);
  sceneLight->SetPositional(false);
  renderer->AddLight(sceneLight);
  int sceneRelit = 0, sceneReused = 0;
  const double sceneMs = orbit(sceneRelit, sceneReused);
  renderer->RemoveAllLights();
  int headRelit = 0, headReused = 0;
  const double headMs = orbit(headRelit, headReused);
  auto* headlight = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));
  VOXELGI_CHECK(renderer->GetLights()->GetNumberOfItems() == 1 && headlight->LightTypeIsHeadlight(),
    "no automatic headlight");
  std::cout << "ms per orbit frame: headlight " << headMs << ", scene light " << sceneMs
            << " (ratio " << headMs / sceneMs << "); frames relit: headlight " << headRelit
            << ", scene light " << sceneRelit << "; reused traces " << headReused << " and "
            << sceneReused << " of " << Frames << std::endl;
  VOXELGI_CHECK(sceneRelit == 0, "the scene light relit " << sceneRelit << " frames");
  VOXELGI_CHECK(headRelit == 1, "the headlight relit " << headRelit << " frames over 60 degrees");
  VOXELGI_CHECK(headReused == Frames && sceneReused == Frames,
    "reused " << headReused << " and " << sceneReused << " of " << Frames);
  VOXELGI_CHECK(voxelgi_test::Bounded(gi), "non-finite values");
  return voxelgi_test::ImageMatches(argc, argv, window);
}
}

int TestGIRealPrograms(int argc, char* argv[])
{
  const std::string which = argc > 1 ? argv[1] : "";
  if (which == "viewports")
  {
    return Viewports(argc, argv);
  }
  if (which == "headlight")
  {
    return Headlight(argc, argv);
  }
  std::cerr << "Usage: TestGIRealPrograms viewports|headlight" << std::endl;
  return EXIT_FAILURE;
}
