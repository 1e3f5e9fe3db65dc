// Windows that close, voxel sources that go away, EGL contexts that move between windows and
// threads: no frozen, stale or borrowed frames. Each case compares the pass's image with a
// twin window's at every frame of a camera path, or asserts that GI is off with one message.
//
//   TestGIReliability <case>     one case (CTest runs each as VoxelGI::Reliability.<case>)
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIEGLRenderWindow.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <functional>
#include <future>
#include <limits>
#include <map>
#include <string>
#include <thread>
#include <vector>

namespace
{
using voxelgi_test::Bounded;
using voxelgi_test::Composite;
using voxelgi_test::MaxDifference;
using voxelgi_test::Messages;

// A Cornell box in a window of its own.
struct Box : voxelgi_test::GIWindow
{
  explicit Box(vtkRenderWindow* window = nullptr)
    : GIWindow(nullptr, 32, 80)
  {
    if (window) // replaces the GLX window of GIWindow
    {
      this->Window->RemoveRenderer(this->Renderer);
      window->SetSize(80, 80);
      window->AddRenderer(this->Renderer);
      this->Shown = window;
    }
    else
    {
      this->Shown = this->Window;
    }
    vtkVoxelGIScenes::AddCornellBox(this->Renderer);
    this->Renderer->ResetCamera();
  }
  vtkRenderWindow* Shown;
};

// Turns both boxes' cameras and renders both, `frames` times; every composite of `box` must
// equal the twin's.
bool FollowsTwin(Box& box, Box& twin, const char* after, int frames = 4)
{
  for (int frame = 0; frame < frames; ++frame)
  {
    for (Box* b : { &box, &twin })
    {
      b->Renderer->GetActiveCamera()->Azimuth(12.0);
      b->Shown->Render();
    }
    const double d = MaxDifference(Composite(box.GI), Composite(twin.GI));
    std::cout << "after " << after << ", frame " << frame << ": GI active "
              << box.GI->GetGIActive() << ", largest difference to the twin " << d << std::endl;
    if (!box.GI->GetGIActive() || d != 0.0)
    {
      return false;
    }
  }
  return true;
}

// Two renderers of one window: a voxel source and a pass tracing its voxels.
struct Sharing
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Source, Sharer;
  vtkNew<vtkVoxelGIPass> SourceGI, SharerGI;
  Messages Log{ SharerGI };
  explicit Sharing(bool sharerFirst)
  {
    this->Window->SetSize(160, 80);
    for (vtkVoxelGIPass* gi : { this->SourceGI.Get(), this->SharerGI.Get() })
    {
      gi->SetSoftwareProfileToOff();
      gi->SetVoxelResolution(32);
    }
    this->SharerGI->SetVoxelSource(this->SourceGI);
    this->Source->SetViewport(0.0, 0.0, 0.5, 1.0);
    this->Sharer->SetViewport(0.5, 0.0, 1.0, 1.0);
    this->Source->SetPass(this->SourceGI);
    this->Sharer->SetPass(this->SharerGI);
    for (vtkRenderer* r : { this->Source.Get(), this->Sharer.Get() })
    {
      vtkVoxelGIScenes::AddCornellBox(r);
      r->ResetCamera();
    }
    this->Window->AddRenderer(sharerFirst ? this->Sharer : this->Source);
    this->Window->AddRenderer(sharerFirst ? this->Source : this->Sharer);
  }
};

const char* const Stale = "did not render in this window's last frame";

// The source goes away (`leave`) and comes back (`back`): while it is away the sharer
// renders VTK's image and says why once; then it traces again.
int SourceGoesAway(const std::function<void(Sharing&)>& leave,
  const std::function<void(Sharing&)>& back)
{
  Sharing s(false);
  for (int frame = 0; frame < 2; ++frame)
  {
    s.Window->Render();
  }
  VOXELGI_CHECK(s.SharerGI->GetGIActive() && s.Log.Count == 0, "no GI to start with: " << s.Log.Text);
  leave(s);
  for (int frame = 0; frame < 3; ++frame)
  {
    s.Window->Render();
    std::cout << "away, frame " << frame << ": sharer GI active " << s.SharerGI->GetGIActive()
              << ", props " << s.SharerGI->GetNumberOfRenderedProps() << std::endl;
    VOXELGI_CHECK(!s.SharerGI->GetGIActive() && s.SharerGI->GetNumberOfRenderedProps() > 0,
      "the sharer traced voxels its source no longer keeps, or drew nothing");
  }
  const std::size_t first = s.Log.Text.find(Stale);
  VOXELGI_CHECK(first != std::string::npos && s.Log.Text.find(Stale, first + 1) == std::string::npos,
    "not said once: " << s.Log.Text);
  back(s);
  for (int frame = 0; frame < 2; ++frame)
  {
    s.Window->Render();
  }
  VOXELGI_CHECK(s.SharerGI->GetGIActive() && Bounded(s.SharerGI), "GI did not come back");
  return EXIT_SUCCESS;
}

// EGL windows need the surfaceless platform (set by CTest) and the GLEW shim.
int OnePassTwoEGLWindows()
{
  vtkNew<vtkVoxelGIEGLRenderWindow> one, two, lone;
  Box first(one), second(two), twin(lone);
  second.Renderer->SetPass(first.GI); // one pass takes turns on two windows
  for (int frame = 0; frame < 4; ++frame)
  {
    Box& b = frame % 2 == 0 ? first : second;
    b.Shown->Render();
    twin.Shown->Render();
    const double d = MaxDifference(Composite(first.GI), Composite(twin.GI));
    std::cout << "frame " << frame << ": largest difference to a pass of its own " << d
              << std::endl;
    VOXELGI_CHECK(first.GI->GetGIActive() && d == 0.0, "a window of the shared pass differs");
  }
  return EXIT_SUCCESS;
}

int EGLWindowInAnotherThread()
{
  vtkNew<vtkVoxelGIEGLRenderWindow> window;
  Box box(window);
  Messages log(window);
  // A worker renders and keeps the context current until told to release it.
  std::promise<void> rendered, release;
  std::thread worker([&] {
    window->Render();
    rendered.set_value();
    release.get_future().wait();
    window->ReleaseCurrent();
  });
  rendered.get_future().wait();
  vtkNew<vtkVoxelGIEGLRenderWindow> other;
  Box elsewhere(other);
  other->Render(); // a context current in this thread
  window->Render();
  std::cout << "messages: " << log.Text << std::endl;
  VOXELGI_CHECK(log.Has("current in another thread"), "no message: " << log.Text);
  vtkNew<vtkFloatArray> pixels;
  VOXELGI_CHECK(!box.GI->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, pixels),
    "the read-back returned another context's image");
  release.set_value();
  worker.join();
  window->Render();
  VOXELGI_CHECK(box.GI->GetGIActive() && Composite(box.GI), "no GI after the worker released");
  return EXIT_SUCCESS;
}

// Sixteen lights' maps at ShadowMapResolution 4096 (3.5 GiB) under an address-space limit
// that leaves 800 MiB: the maps are made smaller, said once with the figures, GI stays on;
// with two lights left they fit at full size again.
int ShadowMapsDegrade()
{
  Box box;
  Messages log(box.GI);
  box.GI->SetShadowMapResolution(128);
  std::vector<vtkSmartPointer<vtkLight>> added;
  for (int i = 0; i < 15; ++i) // with the box's own point light: 8 point lights, 8 spots
  {
    auto light = vtkSmartPointer<vtkLight>::New();
    light->SetLightTypeToSceneLight();
    light->SetPositional(true);
    light->SetPosition(1.0 + 0.2 * i, 4.5, 2.75);
    light->SetFocalPoint(2.75, 0.0, 2.75);
    light->SetConeAngle(i < 7 ? 180.0 : 30.0);
    light->SetIntensity(0.05);
    box.Renderer->AddLight(light);
    added.push_back(light);
  }
  box.Window->Render(); // its shaders built and volumes made before the limit
  struct rlimit before;
  getrlimit(RLIMIT_AS, &before);
  long long pages = 0;
  std::ifstream("/proc/self/statm") >> pages;
  struct rlimit limited = before;
  limited.rlim_cur = static_cast<rlim_t>(pages * sysconf(_SC_PAGESIZE)) + (800u << 20);
  setrlimit(RLIMIT_AS, &limited);
  const unsigned long long map = 4096ull * 4096 * 4;
  box.GI->SetShadowMapResolution(4096);
  box.Window->Render();
  const unsigned long long degraded = box.GI->GetAllocatedBytes(vtkVoxelGIPass::RESOURCE_SHADOW_MAPS);
  const int said = log.Count;
  box.Window->Render();
  for (std::size_t i = 0; i + 1 < added.size(); ++i) // keep one spot light
  {
    box.Renderer->RemoveLight(added[i]);
  }
  box.Window->Render();
  const unsigned long long full = box.GI->GetAllocatedBytes(vtkVoxelGIPass::RESOURCE_SHADOW_MAPS);
  const bool active = box.GI->GetGIActive();
  setrlimit(RLIMIT_AS, &before);
  std::cout << "maps of 56 layers: " << (degraded >> 20) << " MiB; of 7 layers: " << (full >> 20)
            << " MiB; messages: " << log.Text << std::endl;
  VOXELGI_CHECK(said == 1 && log.Has("ShadowMapResolution 4096 needs 3584 MiB for 56 shadow maps") &&
      log.Has("MiB are free (address space") && log.Has("they are rendered at 1024 texels (224 MiB)"),
    "not said once with the figures");
  VOXELGI_CHECK(degraded == 56 * map / 16, "the maps are not 1024 texels wide");
  VOXELGI_CHECK(active && full == 7 * map && log.Count == 1, "not full size again with two lights");
  VOXELGI_CHECK(box.GI->GetVoxelMemoryBytes() == box.GI->GetRequiredVoxelMemoryBytes(true),
    "the need does not count the maps: holds " << box.GI->GetVoxelMemoryBytes() << ", needs "
                                               << box.GI->GetRequiredVoxelMemoryBytes(true));
  return EXIT_SUCCESS;
}

// An actor with one Inf vertex: VTK's bounds of it are infinite, yet its other triangles are
// voxelized (the grid fitted to its finite points) and the warning is said once.
int InfVertexKeepsActor()
{
  Box box;
  box.Renderer->RemoveAllViewProps();
  vtkNew<vtkPoints> points;
  const double inf = std::numeric_limits<double>::infinity();
  const double corners[6][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 0, 1 }, { 1, 0, 1 }, { 2, 0, 1 },
    { inf, 0, 0 } };
  for (const auto& c : corners)
  {
    points->InsertNextPoint(c);
  }
  vtkNew<vtkCellArray> triangles;
  const vtkIdType first[3] = { 0, 2, 1 }, second[3] = { 3, 4, 5 };
  triangles->InsertNextCell(3, first);
  triangles->InsertNextCell(3, second);
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(triangles);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  box.Renderer->AddActor(actor);
  box.Renderer->ResetCamera(0, 2, 0, 0, 0, 1);
  Messages log(box.GI);
  for (int frame = 0; frame < 3; ++frame)
  {
    box.Window->Render();
  }
  vtkNew<vtkImageData> albedo;
  VOXELGI_CHECK(box.GI->GetGIActive() && box.GI->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, albedo),
    "no GI: " << log.Text);
  vtkDataArray* voxels = albedo->GetPointData()->GetScalars();
  vtkIdType occupied = 0;
  for (vtkIdType v = 0; v < voxels->GetNumberOfTuples(); ++v)
  {
    occupied += voxels->GetComponent(v, 3) > 0.0 ? 1 : 0;
  }
  std::cout << occupied << " voxels occupied; messages: " << log.Text << std::endl;
  VOXELGI_CHECK(occupied > 0, "the actor was left out");
  VOXELGI_CHECK(log.Count == 1 && log.Has("1 of 6 points with NaN or Inf coordinates"),
    "not said once");
  return EXIT_SUCCESS;
}

// Without the GLEW shim VTK reports GLEW's failure under EGL: once, with the remedy.
int EGLWithoutShim()
{
  vtkNew<vtkVoxelGIEGLRenderWindow> window;
  Box box(window);
  Messages log(window);
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
  }
  const std::string failed = "GLEW could not be initialized";
  const std::size_t first = log.Text.find(failed);
  std::cout << "messages: " << log.Text << std::endl;
  VOXELGI_CHECK(first != std::string::npos && log.Text.find(failed, first + 1) == std::string::npos,
    "GLEW's failure not said exactly once");
  VOXELGI_CHECK(log.Has("preload libVoxelGIGlewEGLShim.so") && log.Count == 2, "no remedy said once");
  VOXELGI_CHECK(box.GI->GetGIActive(), "no GI");
  return EXIT_SUCCESS;
}

const voxelgi_test::Cases& Cases()
{
  static const voxelgi_test::Cases cases = {
    { "ClosingWindowKeepsOthersFollowing",
      [] {
        // A's objects freed while B's context is current must not free B's.
        Box a, b, twin;
        for (Box* w : { &a, &b, &twin })
        {
          w->Window->Render();
        }
        b.Window->MakeCurrent();
        a.Window->RemoveRenderer(a.Renderer);
        VOXELGI_CHECK(FollowsTwin(b, twin, "removing A's renderer"), "B's GI froze");
        a.Window->AddRenderer(a.Renderer);
        a.Window->Render();
        b.Window->MakeCurrent();
        a.GI->ReleaseGraphicsResources(a.Window);
        VOXELGI_CHECK(FollowsTwin(b, twin, "releasing A's pass"), "B's GI froze");
        return EXIT_SUCCESS;
      } },
    { "SourceRendererRemoved",
      [] {
        return SourceGoesAway([](Sharing& s) { s.Window->RemoveRenderer(s.Source); },
          [](Sharing& s) { s.Window->AddRenderer(s.Source); });
      } },
    { "SourceNotDrawn",
      [] {
        return SourceGoesAway(
          [](Sharing& s) { s.Source->DrawOff(); }, [](Sharing& s) { s.Source->DrawOn(); });
      } },
    { "SourcePassRemoved",
      [] {
        return SourceGoesAway([](Sharing& s) { s.Source->SetPass(nullptr); },
          [](Sharing& s) { s.Source->SetPass(s.SourceGI); });
      } },
    { "SharerBeforeSource",
      [] {
        // Drawn before its source, the sharer traces the source's last frame; a source
        // released in between leaves it VTK's image for that frame, never freed volumes.
        Sharing s(true);
        for (int frame = 0; frame < 3; ++frame)
        {
          s.Window->Render();
        }
        VOXELGI_CHECK(s.SharerGI->GetGIActive() && s.Log.Count == 0,
          "no GI before the source: " << s.Log.Text);
        s.SourceGI->ReleaseGraphicsResources(s.Window);
        s.Window->Render();
        VOXELGI_CHECK(!s.SharerGI->GetGIActive(), "traced a released source's voxels");
        s.Window->Render();
        VOXELGI_CHECK(s.SharerGI->GetGIActive() && s.Log.Count == 0 && Bounded(s.SharerGI),
          "GI did not come back: " << s.Log.Text);
        return EXIT_SUCCESS;
      } },
    { "SharedSourceCannotShare",
      [] {
        // A pass that others share cannot start sharing another's voxels (they would lose GI).
        Sharing s(false);
        vtkNew<vtkVoxelGIPass> other;
        Messages log(s.SourceGI);
        s.SourceGI->SetVoxelSource(other);
        VOXELGI_CHECK(!s.SourceGI->GetVoxelSource() && log.Has("other passes share this pass's voxels"),
          "accepted: " << log.Text);
        s.Window->Render();
        VOXELGI_CHECK(s.SharerGI->GetGIActive(), "the sharer lost GI");
        s.SharerGI->SetVoxelSource(nullptr);
        s.SourceGI->SetVoxelSource(other);
        VOXELGI_CHECK(s.SourceGI->GetVoxelSource() == other.Get() && log.Count == 1,
          "refused once nobody shares it: " << log.Text);
        return EXIT_SUCCESS;
      } },
    { "GIActiveOnlyWhenRendered",
      [] {
        // GetGIActive() answers for the window's last render, not the pass's last frame.
        Box box;
        box.Window->Render();
        VOXELGI_CHECK(box.GI->GetGIActive(), "no GI in the first frame");
        box.Renderer->DrawOff();
        box.Window->Render();
        VOXELGI_CHECK(!box.GI->GetGIActive(), "active in a render its renderer was not drawn");
        box.Renderer->DrawOn();
        box.Window->Render();
        VOXELGI_CHECK(box.GI->GetGIActive(), "GI did not come back");
        box.Renderer->SetPass(nullptr);
        box.Window->Render();
        VOXELGI_CHECK(!box.GI->GetGIActive(), "active in a render after the pass was removed");
        return EXIT_SUCCESS;
      } },
    { "MultiSamplesFollowTheWindow",
      [] {
        // Changing only the window's MultiSamples: every frame equals a fresh window's.
        Box box;
        box.Window->SetMultiSamples(8);
        box.Window->Render();
        std::map<int, vtkSmartPointer<vtkUnsignedCharArray>> images;
        for (int samples : { 0, 4, 8, 2 })
        {
          box.Window->SetMultiSamples(samples);
          box.Window->Render();
          Box fresh;
          fresh.Window->SetMultiSamples(samples);
          fresh.Window->Render();
          vtkNew<vtkUnsignedCharArray> shown, expected;
          box.Window->GetRGBACharPixelData(0, 0, 79, 79, 0, shown);
          fresh.Window->GetRGBACharPixelData(0, 0, 79, 79, 0, expected);
          const double d = MaxDifference(shown, expected);
          std::cout << samples << " samples: GI active " << box.GI->GetGIActive()
                    << ", largest difference to a fresh window " << d << std::endl;
          VOXELGI_CHECK(box.GI->GetGIActive() && d <= 2.0, "stale after MultiSamples " << samples);
          images[samples] = expected.Get();
        }
        // A stale image would show: the edges of 0 and 8 samples differ.
        const double edges = MaxDifference(images[0], images[8]);
        std::cout << "0 against 8 samples: largest difference " << edges << std::endl;
        VOXELGI_CHECK(edges > 20.0, "the sample counts give the same image: nothing measured");
        return EXIT_SUCCESS;
      } },
    { "OnePassTwoEGLWindows", OnePassTwoEGLWindows },
    { "EGLWindowInAnotherThread", EGLWindowInAnotherThread },
    { "EGLWithoutShim", EGLWithoutShim },
    { "ShadowMapsDegrade", ShadowMapsDegrade },
    { "InfVertexKeepsActor", InfVertexKeepsActor },
  };
  return cases;
}
}

int TestGIReliability(int argc, char* argv[])
{
  int result = EXIT_FAILURE;
  if (voxelgi_test::RunNamedCase(Cases(), argc, argv, result))
  {
    return result;
  }
  std::cerr << "FAILED: name a case" << std::endl;
  return EXIT_FAILURE;
}
