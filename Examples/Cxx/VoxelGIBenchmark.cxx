// Per-stage timing of vtkVoxelGIPass over scripted frame sequences (a benchmark, not a test).
//
//   VoxelGIBenchmark [--scene cornell|field] [--objects N] [--size WxH] [--resolution R]
//                    [--frames F] [--warmup W] [--egl] [--csv FILE] [--json FILE]
//
// Sequences: static (nothing changes), orbit (camera only), light (one light moves),
// one-moving (one dynamic actor moves), all-moving (every actor moves), and plain (GI off,
// VTK alone, static). Each frame's wall time (after glFinish) and per-stage GPU times
// (timer queries) go to the CSV; the JSON and the printed table hold medians per sequence.
#include "vtkVoxelGIEGLRenderWindow.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace
{
struct Options
{
  std::string Scene = "cornell";
  int Objects = 64;
  int Width = 640;
  int Height = 480;
  int Resolution = 128;
  int Frames = 20;
  int Warmup = 3;
  bool EGL = false;
  std::string CSV = "voxelgi-benchmark.csv";
  std::string JSON = "voxelgi-benchmark.json";
};

vtkActor* AddActor(vtkRenderer* renderer, vtkAlgorithm* source, double r, double g, double b)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  renderer->AddActor(actor);
  return actor;
}

// N spheres and boxes on a ground plane under a directional light (an open scene with AO).
void AddField(vtkRenderer* renderer, int objects)
{
  const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(objects))));
  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-1, 0, -1);
  ground->SetPoint1(-1, 0, 2 * side + 1);
  ground->SetPoint2(2 * side + 1, 0, -1);
  AddActor(renderer, ground, 0.8, 0.8, 0.8);
  for (int i = 0; i < objects; ++i)
  {
    const double x = 2.0 * (i % side) + 0.5, z = 2.0 * (i / side) + 0.5;
    const double hue = static_cast<double>(i) / objects;
    if (i % 2)
    {
      vtkNew<vtkSphereSource> sphere;
      sphere->SetCenter(x, 0.6, z);
      sphere->SetRadius(0.6);
      sphere->SetThetaResolution(24);
      sphere->SetPhiResolution(24);
      AddActor(renderer, sphere, 0.9 - 0.6 * hue, 0.4, 0.3 + 0.6 * hue);
    }
    else
    {
      vtkNew<vtkCubeSource> cube;
      cube->SetBounds(x - 0.5, x + 0.5, 0.0, 1.0 + (i % 3), z - 0.5, z + 0.5);
      AddActor(renderer, cube, 0.3, 0.5 + 0.4 * hue, 0.8 - 0.5 * hue);
    }
  }
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(side + 3.0, 10.0, side + 6.0);
  sun->SetFocalPoint(side, 0.0, side);
  renderer->AddLight(sun);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(side, 0.0, side);
  camera->SetPosition(side + 1.5 * side, 1.2 * side + 2.0, side + 2.0 * side + 3.0);
  renderer->ResetCameraClippingRange();
}

// The GL renderer's name, from VTK's capability report (after a render).
std::string RendererName(vtkRenderWindow* window)
{
  const std::string report = window->ReportCapabilities() ? window->ReportCapabilities() : "";
  const std::string key = "OpenGL renderer string:";
  const std::size_t at = report.find(key);
  if (at == std::string::npos)
  {
    return "unknown";
  }
  std::string name = report.substr(at + key.size(), report.find('\n', at) - at - key.size());
  name.erase(0, name.find_first_not_of(' '));
  return name;
}

double Median(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

bool Parse(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (arg == "--scene") o.Scene = next();
    else if (arg == "--objects") o.Objects = std::atoi(next().c_str());
    else if (arg == "--size")
    {
      const std::string v = next();
      o.Width = std::atoi(v.c_str());
      o.Height = std::atoi(v.substr(v.find('x') + 1).c_str());
    }
    else if (arg == "--resolution") o.Resolution = std::atoi(next().c_str());
    else if (arg == "--frames") o.Frames = std::atoi(next().c_str());
    else if (arg == "--warmup") o.Warmup = std::atoi(next().c_str());
    else if (arg == "--egl") o.EGL = true;
    else if (arg == "--csv") o.CSV = next();
    else if (arg == "--json") o.JSON = next();
    else
    {
      std::cerr << "unknown argument " << arg << std::endl;
      return false;
    }
  }
  return o.Width > 0 && o.Height > 0 && o.Frames > 0 && (o.Scene == "cornell" || o.Scene == "field");
}
}

int main(int argc, char* argv[])
{
  Options o;
  if (!Parse(argc, argv, o))
  {
    std::cerr << "usage: VoxelGIBenchmark [--scene cornell|field] [--objects N] [--size WxH] "
                 "[--resolution R] [--frames F] [--warmup W] [--egl] [--csv FILE] [--json FILE]"
              << std::endl;
    return EXIT_FAILURE;
  }

  vtkNew<vtkRenderer> renderer;
  if (o.Scene == "cornell")
  {
    vtkVoxelGIScenes::AddCornellBox(renderer);
  }
  else
  {
    AddField(renderer, o.Objects);
  }
  std::vector<vtkActor*> actors;
  vtkActorCollection* collection = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkActor* actor = collection->GetNextActor(it))
  {
    actors.push_back(actor);
  }
  // The mover: the Cornell box's short block, or the field's first object.
  vtkActor* mover = actors[o.Scene == "cornell" ? 5 : 1];
  vtkVoxelGIPass::SetPropDynamic(mover, true);
  vtkLight* light = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));

  vtkSmartPointer<vtkRenderWindow> window = o.EGL
    ? vtkSmartPointer<vtkRenderWindow>(vtkSmartPointer<vtkVoxelGIEGLRenderWindow>::New())
    : vtkSmartPointer<vtkRenderWindow>::New();
  window->SetSize(o.Width, o.Height);
  window->SetOffScreenRendering(true);
  window->AddRenderer(renderer);
  vtkNew<vtkVoxelGIPass> gi;
  gi->SetVoxelResolution(o.Resolution);
  gi->TimeStagesOn();
  renderer->SetPass(gi);

  struct Sequence
  {
    std::string Name;
    std::function<void(int)> Step;
    bool GI;
  };
  double lightBase[3];
  light->GetPosition(lightBase);
  const std::vector<Sequence> sequences = {
    { "static", [](int) {}, true },
    { "orbit", [&](int) { renderer->GetActiveCamera()->Azimuth(2.0); }, true },
    { "light",
      [&](int f) { light->SetPosition(lightBase[0] + 0.3 * std::sin(0.3 * f), lightBase[1],
                     lightBase[2] + 0.3 * std::cos(0.3 * f)); },
      true },
    { "one-moving", [&](int f) { mover->SetPosition(0.0, 0.0, 0.2 * std::sin(0.3 * f)); }, true },
    { "all-moving",
      [&](int f) {
        for (vtkActor* actor : actors)
        {
          actor->SetPosition(0.0, 0.02 * std::sin(0.3 * f), 0.0);
        }
      },
      true },
    { "plain", [](int) {}, false },
  };

  std::ofstream csv(o.CSV);
  csv << "sequence,frame,frame_ms";
  for (int s = 0; s < vtkVoxelGIPass::NUMBER_OF_STAGES; ++s)
  {
    csv << "," << vtkVoxelGIPass::GetStageName(s) << "_ms";
  }
  csv << ",stages_run\n";

  std::map<std::string, std::vector<std::vector<double>>> samples; // per sequence: columns
  for (const Sequence& sequence : sequences)
  {
    gi->SetEnabled(sequence.GI);
    auto& columns = samples[sequence.Name];
    columns.assign(vtkVoxelGIPass::NUMBER_OF_STAGES + 1, {});
    for (int f = -o.Warmup; f < o.Frames; ++f)
    {
      sequence.Step(f);
      window->WaitForCompletion();
      const auto start = std::chrono::steady_clock::now();
      window->Render();
      window->WaitForCompletion();
      const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      if (f < 0)
      {
        continue;
      }
      csv << sequence.Name << "," << f << "," << ms;
      columns[0].push_back(ms);
      std::string ran;
      for (int s = 0; s < vtkVoxelGIPass::NUMBER_OF_STAGES; ++s)
      {
        csv << "," << gi->GetStageTime(s);
        columns[s + 1].push_back(gi->GetStageTime(s));
        if (gi->GetStageRan(s))
        {
          ran += std::string(ran.empty() ? "" : "|") + vtkVoxelGIPass::GetStageName(s);
        }
      }
      csv << "," << ran << "\n";
    }
  }

  std::ofstream json(o.JSON);
  json << "{\n  \"scene\": \"" << o.Scene << "\", \"objects\": " << o.Objects << ", \"width\": "
       << o.Width << ", \"height\": " << o.Height << ", \"resolution\": " << o.Resolution
       << ", \"frames\": " << o.Frames << ",\n  \"renderer\": \"" << RendererName(window)
       << "\",\n  \"median_ms\": {\n";
  std::cout << std::fixed << std::setprecision(2) << "\nmedian ms on " << RendererName(window)
            << ", " << o.Scene << " " << o.Width << "x" << o.Height << ", " << o.Resolution
            << "^3 voxels, " << o.Frames << " frames\n"
            << std::setw(12) << "sequence" << std::setw(10) << "frame";
  for (int s = 0; s < vtkVoxelGIPass::NUMBER_OF_STAGES; ++s)
  {
    std::cout << std::setw(10) << std::string(vtkVoxelGIPass::GetStageName(s)).substr(0, 9);
  }
  std::cout << "\n";
  for (std::size_t q = 0; q < sequences.size(); ++q)
  {
    const std::string& name = sequences[q].Name;
    const auto& columns = samples[name];
    json << "    \"" << name << "\": {\"frame\": " << Median(columns[0]);
    std::cout << std::setw(12) << name << std::setw(10) << Median(columns[0]);
    for (int s = 0; s < vtkVoxelGIPass::NUMBER_OF_STAGES; ++s)
    {
      json << ", \"" << vtkVoxelGIPass::GetStageName(s) << "\": " << Median(columns[s + 1]);
      std::cout << std::setw(10) << Median(columns[s + 1]);
    }
    json << "}" << (q + 1 < sequences.size() ? "," : "") << "\n";
    std::cout << "\n";
  }
  json << "  }\n}\n";
  std::cout << "wrote " << o.CSV << " and " << o.JSON << std::endl;
  return EXIT_SUCCESS;
}
