// Per-stage timing of vtkVoxelGIPass over scripted frame sequences (a benchmark, not a test).
//
//   VoxelGIBenchmark [--scene cornell|field|atrium|sphere|volume|translucent] [--objects N] [--triangles N]
//                    [--size WxH] [--resolution R] [--frames F] [--warmup W] [--trace-scale S]
//                    [--multisamples N] [--egl] [--temporal-reuse 0|1] [--bounces N]
//                    [--update-interval N] [--viewports N] [--shared-grid 0|1]
//                    [--set SETTING=VALUE ...]
//                    [--sequences NAME,NAME,...] [--csv FILE] [--json FILE] [--image FILE]
//
// Scenes: the Cornell box (36 triangles), a field of N spheres and boxes on a ground plane
// (N + 1 actors), an atrium of Sponza scale (about 280k triangles: columns, arches,
// galleries, drapes, coloured), one tessellated sphere of about N triangles, a 256^3 volume
// (VTK's wavelet, GPU ray cast) over a floor beside a sphere, and the study's translucent
// surfaces (vtkVoxelGIScenes::AddTranslucentSurfaces: a glass canopy and a glass ball).
// Sequences: static (nothing changes), orbit (camera only), headlight-orbit (the same orbit
// with the scene's lights off and VTK's headlight on: the light turns with the camera), light
// (one light moves), one-moving (one dynamic actor moves), all-moving (every actor moves),
// new-data (every actor's data replaced, as by a time step: its points modified), plain (GI off,
// VTK alone, static), plain-new-data (GI off, new data each frame) and transfer-function (the
// volumes' opacity changes: resampled every frame), and light-interactive, one-moving-interactive
// and all-moving-interactive (those changes while the window renders interactively, at an
// interactor style's desired update rate); --sequences runs some of them. Per frame: the wall time of Render() with glFinish, its CPU time (Render() returning,
// without glFinish), the GPU time span of the frame (two timestamp queries) and per-stage GPU times
// (timer queries) go to the CSV; the JSON and the printed table hold medians per sequence, and the
// mean frame (a sequence whose frames differ in kind, as the headlight orbit's relights, is judged
// by it). --set sets any setting of the settings table (vtkVoxelGISettings), e.g. --set
// DiffuseConeCount=16; the JSON lists them. Each sequence runs twice: with the stage timers for the
// stage times, then without them for the frame, CPU and span.
// --viewports N tiles the window with N renderers showing the same props, each camera turned
// by 10 degrees from the last, each with a pass of the same settings; with --shared-grid 1 the
// others share the first pass's voxel grid (vtkVoxelGIPass::SetVoxelSource). Camera
// sequences move every camera; stage times are the first pass's.
#include "vtkVoxelGIEGLRenderWindow.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"
#include "vtkVoxelGISettings.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCubeSource.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRTAnalyticSource.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"
#include "vtkVolumeProperty.h"
#include "vtkCylinderSource.h"
#include "vtkPNGWriter.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkWindowToImageFilter.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkCell.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkParametricEllipsoid.h"
#include "vtk_glew.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
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
  long long Triangles = 100000;
  std::string Sequences; // comma-separated names; empty: all
  int Width = 640;
  int Height = 480;
  int Resolution = 128;
  int Frames = 20;
  int Warmup = 3;
  double TraceScale = 1.0;
  bool TemporalReuse = true;
  int Bounces = -1;        // -1: the default
  int UpdateInterval = 0;  // > 0: revoxelize every N frames (UpdatePolicy EveryNFrames)
  int MultiSamples = -1; // -1: VTK's default
  int Viewports = 1;
  bool SharedGrid = false;
  bool EGL = false;
  std::string CSV = "voxelgi-benchmark.csv";
  std::string JSON = "voxelgi-benchmark.json";
  std::string Image; // PNG of the first GI frame, if given
  std::vector<std::pair<std::string, double>> Settings; // --set NAME=VALUE
};

// N spheres and boxes on a ground plane under a directional light (an open scene with AO).
void AddField(vtkRenderer* renderer, int objects)
{
  const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(objects))));
  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-1, 0, -1);
  ground->SetPoint1(-1, 0, 2 * side + 1);
  ground->SetPoint2(2 * side + 1, 0, -1);
  vtkVoxelGIScenes::AddSource(renderer, ground, 0.8, 0.8, 0.8);
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
      vtkVoxelGIScenes::AddSource(renderer, sphere, 0.9 - 0.6 * hue, 0.4, 0.3 + 0.6 * hue);
    }
    else
    {
      vtkNew<vtkCubeSource> cube;
      cube->SetBounds(x - 0.5, x + 0.5, 0.0, 1.0 + (i % 3), z - 0.5, z + 0.5);
      vtkVoxelGIScenes::AddSource(renderer, cube, 0.3, 0.5 + 0.4 * hue, 0.8 - 0.5 * hue);
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

// One sphere of about `triangles` triangles (a parametric ellipsoid: two per grid cell) under a
// directional light: the cost of voxelizing one mesh against its size.
void AddSphere(vtkRenderer* renderer, long long triangles)
{
  const int n = std::max(4, static_cast<int>(std::lround(std::sqrt(triangles / 2.0))));
  vtkNew<vtkParametricEllipsoid> ellipsoid;
  vtkNew<vtkParametricFunctionSource> sphere;
  sphere->SetParametricFunction(ellipsoid);
  sphere->SetUResolution(n);
  sphere->SetVResolution(n);
  sphere->GenerateTextureCoordinatesOff();
  vtkVoxelGIScenes::AddSource(renderer, sphere, 0.8, 0.5, 0.3);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(2.0, 4.0, 3.0);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(sun);
  renderer->ResetCamera();
}

// A 256^3 volume (VTK's wavelet through colour and opacity transfer functions, GPU ray cast)
// over a floor, beside a sphere, under a sun.
void AddVolume(vtkRenderer* renderer)
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-128, 127, -128, 127, -128, 127);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(60.0, 0.0);
  opacity->AddPoint(160.0, 0.05);
  opacity->AddPoint(280.0, 0.5);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(60.0, 0.8, 0.3, 0.1);
  color->AddRGBPoint(280.0, 1.0, 0.95, 0.8);
  vtkNew<vtkGPUVolumeRayCastMapper> mapper;
  mapper->SetInputConnection(wavelet->GetOutputPort());
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->GetProperty()->SetScalarOpacity(opacity);
  volume->GetProperty()->SetColor(color);
  volume->GetProperty()->SetScalarOpacityUnitDistance(4.0);
  volume->GetProperty()->SetInterpolationTypeToLinear();
  renderer->AddVolume(volume);
  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(-200.0, -130.0, -200.0);
  floor->SetPoint1(-200.0, -130.0, 200.0);
  floor->SetPoint2(300.0, -130.0, -200.0);
  vtkVoxelGIScenes::AddSource(renderer, floor, 0.8, 0.8, 0.8);
  vtkNew<vtkSphereSource> ball;
  ball->SetCenter(200.0, -60.0, 0.0);
  ball->SetRadius(70.0);
  ball->SetThetaResolution(64);
  ball->SetPhiResolution(64);
  vtkVoxelGIScenes::AddSource(renderer, ball, 0.3, 0.5, 0.9);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(-1.0, 3.0, 1.0);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(sun);
  renderer->ResetCamera();
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

vtkActor* AddPlaced(vtkRenderer* renderer, vtkAlgorithm* source, vtkTransform* transform,
  double r, double g, double b)
{
  vtkNew<vtkTransformPolyDataFilter> place;
  place->SetInputConnection(source->GetOutputPort());
  place->SetTransform(transform);
  return vtkVoxelGIScenes::AddSource(renderer, place, r, g, b);
}

// A Sponza-like atrium, 30 x 12 x 14 units: floor, side walls, two rows of columns carrying
// arches and a gallery floor, and waving drapes between the columns. About 280k triangles.
void AddAtrium(vtkRenderer* renderer)
{
  const double length = 30.0, width = 12.0, height = 14.0;
  auto plane = [&](double ox, double oy, double oz, double ax, double ay, double az, double bx,
                 double by, double bz, int resolution, double r, double g, double b) {
    vtkNew<vtkPlaneSource> quad;
    quad->SetOrigin(ox, oy, oz);
    quad->SetPoint1(ax, ay, az);
    quad->SetPoint2(bx, by, bz);
    quad->SetResolution(resolution, resolution);
    return vtkVoxelGIScenes::AddSource(renderer, quad, r, g, b);
  };
  plane(0, 0, 0, 0, 0, width, length, 0, 0, 64, 0.75, 0.7, 0.6); // floor
  plane(0, 0, 0, length, 0, 0, 0, height, 0, 32, 0.8, 0.75, 0.65); // walls
  plane(0, 0, width, 0, height, width, length, 0, width, 32, 0.8, 0.75, 0.65);
  for (int side = 0; side < 2; ++side)
  {
    const double z = side ? width - 2.5 : 2.5;
    for (int i = 0; i < 10; ++i)
    {
      const double x = 1.5 + 3.0 * i;
      vtkNew<vtkCylinderSource> column;
      column->SetResolution(64);
      column->SetRadius(0.4);
      column->SetHeight(6.0);
      vtkNew<vtkTransform> t;
      t->Translate(x, 3.0, z);
      AddPlaced(renderer, column, t, 0.85, 0.82, 0.75);
      vtkNew<vtkCylinderSource> upper; // gallery columns
      upper->SetResolution(64);
      upper->SetRadius(0.3);
      upper->SetHeight(4.5);
      vtkNew<vtkTransform> tu;
      tu->Translate(x, 9.75, z);
      AddPlaced(renderer, upper, tu, 0.85, 0.82, 0.75);
      if (i < 9)
      {
        vtkNew<vtkParametricTorus> torus; // an arch: the upper half of a torus
        torus->SetRingRadius(1.5);
        torus->SetCrossSectionRadius(0.25);
        torus->SetMaximumU(vtkMath::Pi());
        vtkNew<vtkParametricFunctionSource> arch;
        arch->SetParametricFunction(torus);
        arch->SetUResolution(128);
        arch->SetVResolution(30);
        vtkNew<vtkTransform> ta;
        ta->Translate(x + 1.5, 6.0, z);
        AddPlaced(renderer, arch, ta, 0.8, 0.7, 0.55);
        // drapes between the lower columns, rippled
        vtkNew<vtkPlaneSource> drape;
        drape->SetResolution(54, 54);
        drape->SetOrigin(0, 0, 0);
        drape->SetPoint1(2.2, 0, 0);
        drape->SetPoint2(0, 4.0, 0);
        vtkNew<vtkTransform> td;
        td->Translate(x + 0.4, 0.8, z + (side ? 0.6 : -0.6));
        const double hue = (i % 3) / 3.0;
        vtkActor* d = AddPlaced(renderer, drape, td, 0.7 - 0.5 * hue, 0.15 + 0.5 * hue, 0.2);
        d->RotateY(side ? 8.0 : -8.0);
      }
    }
    // gallery floor over the arches
    plane(0, 7.8, side ? width - 3.5 : 0, 0, 7.8, side ? width : 3.5, length, 7.8,
      side ? width - 3.5 : 0, 48, 0.7, 0.66, 0.6);
  }
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(length * 0.6, height * 3.0, width * 0.8);
  sun->SetFocalPoint(length * 0.5, 0.0, width * 0.5);
  sun->SetIntensity(1.2);
  renderer->AddLight(sun);
  vtkNew<vtkLight> lamp;
  lamp->SetLightTypeToSceneLight();
  lamp->SetPositional(true);
  lamp->SetConeAngle(90.0);
  lamp->SetPosition(length * 0.2, 3.0, width * 0.5);
  lamp->SetColor(1.0, 0.8, 0.6);
  lamp->SetIntensity(0.6);
  renderer->AddLight(lamp);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(-2.0, 4.0, width * 0.5);
  camera->SetFocalPoint(length, 4.5, width * 0.5);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(60.0);
  renderer->ResetCameraClippingRange();
}

double Mean(const std::vector<double>& values)
{
  double sum = 0.0;
  for (double v : values)
  {
    sum += v;
  }
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
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
    else if (arg == "--triangles") o.Triangles = std::atoll(next().c_str());
    else if (arg == "--bounces") o.Bounces = std::atoi(next().c_str());
    else if (arg == "--update-interval") o.UpdateInterval = std::atoi(next().c_str());
    else if (arg == "--sequences") o.Sequences = next();
    else if (arg == "--viewports") o.Viewports = std::atoi(next().c_str());
    else if (arg == "--shared-grid") o.SharedGrid = std::atoi(next().c_str()) != 0;
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
    else if (arg == "--trace-scale") o.TraceScale = std::atof(next().c_str());
    else if (arg == "--temporal-reuse") o.TemporalReuse = std::atoi(next().c_str()) != 0;
    else if (arg == "--multisamples") o.MultiSamples = std::atoi(next().c_str());
    else if (arg == "--csv") o.CSV = next();
    else if (arg == "--json") o.JSON = next();
    else if (arg == "--set")
    {
      const std::string setting = next();
      const size_t eq = setting.find('=');
      o.Settings.emplace_back(setting.substr(0, eq),
        eq == std::string::npos ? 0.0 : std::atof(setting.c_str() + eq + 1));
    }
    else if (arg == "--image") o.Image = next();
    else
    {
      std::cerr << "unknown argument " << arg << std::endl;
      return false;
    }
  }
  return o.Width > 0 && o.Height > 0 && o.Frames > 0 && o.Viewports >= 1 && o.Viewports <= 16 &&
    (o.Scene == "cornell" || o.Scene == "field" || o.Scene == "atrium" || o.Scene == "sphere" ||
      o.Scene == "volume" || o.Scene == "translucent");
}
}

int main(int argc, char* argv[])
{
  Options o;
  if (!Parse(argc, argv, o))
  {
    std::cerr << "usage: VoxelGIBenchmark [--scene cornell|field|atrium|sphere|volume|translucent] [--objects N] "
                 "[--triangles N] [--size WxH] [--resolution R] [--frames F] [--warmup W] "
                 "[--trace-scale S] [--multisamples N] [--egl] [--temporal-reuse 0|1] "
                 "[--bounces N] [--update-interval N] [--viewports N] [--shared-grid 0|1] "
                 "[--sequences NAME,...] [--csv FILE] [--json FILE] [--image FILE]"
              << std::endl;
    return EXIT_FAILURE;
  }

  vtkNew<vtkRenderer> renderer;
  if (o.Scene == "cornell")
  {
    vtkVoxelGIScenes::AddCornellBox(renderer);
  }
  else if (o.Scene == "atrium")
  {
    AddAtrium(renderer);
  }
  else if (o.Scene == "sphere")
  {
    AddSphere(renderer, o.Triangles);
  }
  else if (o.Scene == "volume")
  {
    AddVolume(renderer);
  }
  else if (o.Scene == "translucent")
  {
    vtkVoxelGIScenes::AddTranslucentSurfaces(renderer);
  }
  else
  {
    AddField(renderer, o.Objects);
  }
  std::vector<vtkActor*> actors;
  vtkIdType triangles = 0;
  vtkActorCollection* collection = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkActor* actor = collection->GetNextActor(it))
  {
    actors.push_back(actor);
    actor->GetMapper()->Update();
    if (vtkPolyData* poly = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0)))
    {
      // quads and strips count as the triangles they are drawn as
      for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c)
      {
        const vtkIdType n = poly->GetCell(c)->GetNumberOfPoints();
        triangles += poly->GetCellType(c) == VTK_TRIANGLE_STRIP ? n - 2 : (n >= 3 ? n - 2 : 0);
      }
    }
  }
  std::cout << o.Scene << ": " << actors.size() << " actors, " << triangles << " triangles"
            << std::endl;
  // The mover: the Cornell box's short block, or the field's first object.
  vtkActor* mover = actors[o.Scene == "cornell" ? 5 : std::min<std::size_t>(1, actors.size() - 1)];
  vtkVoxelGIPass::SetPropDynamic(mover, true);
  vtkLight* light = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));

  vtkSmartPointer<vtkRenderWindow> window = o.EGL
    ? vtkSmartPointer<vtkRenderWindow>(vtkSmartPointer<vtkVoxelGIEGLRenderWindow>::New())
    : vtkSmartPointer<vtkRenderWindow>::New();
  window->SetSize(o.Width, o.Height);
  if (o.MultiSamples >= 0)
  {
    window->SetMultiSamples(o.MultiSamples);
  }
  window->SetOffScreenRendering(true);
  window->AddRenderer(renderer);
  vtkNew<vtkVoxelGIPass> gi;
  gi->SetVoxelResolution(o.Resolution);
  gi->SetTraceResolution(o.TraceScale);
  gi->SetTemporalReuse(o.TemporalReuse);
  if (o.Bounces >= 0)
  {
    gi->SetBounces(o.Bounces);
  }
  for (const auto& setting : o.Settings)
  {
    if (!vtkVoxelGISettings::SetValue(gi, setting.first.c_str(), setting.second))
    {
      std::cerr << "unknown setting " << setting.first << "\n";
      return EXIT_FAILURE;
    }
  }
  if (o.UpdateInterval > 0)
  {
    gi->SetUpdatePolicyToEveryNFrames();
    gi->SetUpdateInterval(o.UpdateInterval);
  }
  renderer->SetPass(gi);
  // More viewports on the same props and lights, each with a pass of the same settings.
  std::vector<vtkSmartPointer<vtkRenderer>> renderers{ renderer.GetPointer() };
  std::vector<vtkSmartPointer<vtkVoxelGIPass>> passes{ gi.GetPointer() };
  const int columns = static_cast<int>(std::ceil(std::sqrt(o.Viewports)));
  const int rows = (o.Viewports + columns - 1) / columns;
  for (int i = 0; i < o.Viewports; ++i)
  {
    if (i > 0)
    {
      auto view = vtkSmartPointer<vtkRenderer>::New();
      vtkCollectionSimpleIterator pit;
      renderer->GetViewProps()->InitTraversal(pit);
      while (vtkProp* prop = renderer->GetViewProps()->GetNextProp(pit))
      {
        view->AddViewProp(prop);
      }
      vtkCollectionSimpleIterator lit;
      renderer->GetLights()->InitTraversal(lit);
      while (vtkLight* l = renderer->GetLights()->GetNextLight(lit))
      {
        view->AddLight(l);
      }
      view->GetActiveCamera()->DeepCopy(renderer->GetActiveCamera());
      view->GetActiveCamera()->Azimuth(10.0 * i);
      view->ResetCameraClippingRange();
      auto pass = vtkSmartPointer<vtkVoxelGIPass>::New();
      for (int k = 0; k < vtkVoxelGISettings::GetNumberOfSettings(); ++k)
      {
        const char* name = vtkVoxelGISettings::GetName(k);
        vtkVoxelGISettings::SetValue(pass, name, vtkVoxelGISettings::GetValue(gi, name));
      }
      if (o.SharedGrid)
      {
        pass->SetVoxelSource(gi);
      }
      view->SetPass(pass);
      window->AddRenderer(view);
      renderers.push_back(view);
      passes.push_back(pass);
    }
    const double x = static_cast<double>(i % columns) / columns;
    const double y = static_cast<double>(i / columns) / rows;
    renderers[i]->SetViewport(x, y, x + 1.0 / columns, y + 1.0 / rows);
  }
  const auto orbit = [&renderers]() {
    for (vtkRenderer* view : renderers)
    {
      view->GetActiveCamera()->Azimuth(2.0);
    }
  };

  if (!o.Image.empty())
  {
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->ReadFrontBufferOff();
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(grab->GetOutputPort());
    writer->SetFileName(o.Image.c_str());
    writer->Write();
  }

  struct Sequence
  {
    std::string Name;
    std::function<void(int)> Step;
    bool GI;
    std::function<void(bool)> Setup = [](bool) {}; // true before the sequence, false after
  };
  // The headlight orbit's light: the scene's lights are off meanwhile.
  vtkNew<vtkLight> headlight;
  headlight->SetLightTypeToHeadlight();
  auto useHeadlight = [&](bool on) {
    vtkCollectionSimpleIterator lit;
    renderer->GetLights()->InitTraversal(lit);
    while (vtkLight* l = renderer->GetLights()->GetNextLight(lit))
    {
      l->SetSwitch(l == headlight.GetPointer() || !on);
    }
    for (vtkRenderer* view : renderers)
    {
      if (on)
      {
        view->AddLight(headlight);
      }
      else
      {
        view->RemoveLight(headlight);
      }
    }
  };
  double lightBase[3];
  light->GetPosition(lightBase);
  // A time step that replaces every actor's data: VTK uploads its buffers again, and so does
  // the pass.
  auto newData = [&](int) {
    for (vtkActor* actor : actors)
    {
      if (auto* data = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0)))
      {
        data->GetPoints()->Modified();
      }
    }
  };
  std::vector<Sequence> sequences = {
    { "static", [](int) {}, true },
    { "orbit", [&](int) { orbit(); }, true },
    { "headlight-orbit", [&](int) { orbit(); }, true,
      useHeadlight },
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
    { "new-data", newData, true },
    { "plain", [](int) {}, false },
    { "plain-new-data", newData, false },
    { "transfer-function",
      [&](int f) {
        vtkCollectionSimpleIterator vit;
        renderer->GetVolumes()->InitTraversal(vit);
        while (vtkVolume* volume = renderer->GetVolumes()->GetNextVolume(vit))
        {
          volume->GetProperty()->GetScalarOpacity()->AddPoint(220.0, 0.2 + 0.1 * std::sin(0.3 * f));
        }
      },
      true },
  };

  // The same changes while VTK renders interactively: an interactor style's update rate while
  // a mouse button is down (InteractiveBounces); each runs right after its still sequence.
  for (const std::string name : { "light", "one-moving", "all-moving" })
  {
    const auto still = std::find_if(sequences.begin(), sequences.end(),
      [&name](const Sequence& sequence) { return sequence.Name == name; });
    const Sequence interactive{ name + "-interactive", still->Step, true,
      [&window](bool on) { window->SetDesiredUpdateRate(on ? 15.0 : 0.0001); } };
    sequences.insert(still + 1, interactive);
  }

  std::vector<const Sequence*> selected;
  for (const Sequence& sequence : sequences)
  {
    if (o.Sequences.empty() || ("," + o.Sequences + ",").find("," + sequence.Name + ",") != std::string::npos)
    {
      selected.push_back(&sequence);
    }
  }

  std::ofstream csv(o.CSV);
  csv << "sequence,timers,frame,frame_ms,cpu_ms,gpu_span_ms";
  for (int s = 0; s < vtkVoxelGIPass::NUMBER_OF_STAGES; ++s)
  {
    csv << "," << vtkVoxelGIPass::GetStageName(s) << "_ms";
  }
  csv << ",stages_run\n";

  // The frame's GPU time span: timestamps before and after Render() (the context is the
  // window's throughout).
  window->Render();
  window->MakeCurrent();
  GLuint spanQueries[2];
  glGenQueries(2, spanQueries);
  constexpr int Measured = 3; // frame, CPU, GPU span; then the stages
  std::map<std::string, std::vector<std::vector<double>>> samples; // per sequence: columns
  // Every run starts from the same view, so that sequences that move the camera (the orbit
  // under scene lights and under the headlight) cover the same views.
  std::vector<vtkSmartPointer<vtkCamera>> starts;
  for (vtkRenderer* view : renderers)
  {
    starts.push_back(vtkSmartPointer<vtkCamera>::New());
    starts.back()->DeepCopy(view->GetActiveCamera());
  }
  // Progress on stderr after each run: a software renderer takes minutes per sequence.
  const auto began = std::chrono::steady_clock::now();
  const std::size_t runs = 2 * selected.size();
  std::size_t runsDone = 0;
  for (const Sequence* sequence : selected)
  {
    for (vtkVoxelGIPass* pass : passes)
    {
      pass->SetEnabled(sequence->GI);
    }
    sequence->Setup(true);
    auto& columns = samples[sequence->Name];
    columns.assign(vtkVoxelGIPass::NUMBER_OF_STAGES + Measured, {});
    // Twice: with the stage timers (their read-back waits for the GPU inside Render(), which
    // would count GPU time as CPU time), then without them for the frame, CPU and span.
    for (const bool timed : { true, false })
    {
      gi->SetTimeStages(timed);
      for (std::size_t v = 0; v < renderers.size(); ++v)
      {
        renderers[v]->GetActiveCamera()->DeepCopy(starts[v]);
      }
      for (int f = -o.Warmup; f < o.Frames; ++f)
      {
        sequence->Step(f);
        window->WaitForCompletion();
        window->MakeCurrent();
        glQueryCounter(spanQueries[0], GL_TIMESTAMP);
        const auto start = std::chrono::steady_clock::now();
        window->Render();
        const auto returned = std::chrono::steady_clock::now();
        glQueryCounter(spanQueries[1], GL_TIMESTAMP);
        window->WaitForCompletion();
        const auto finished = std::chrono::steady_clock::now();
        GLuint64 stamps[2] = { 0, 0 };
        glGetQueryObjectui64v(spanQueries[0], GL_QUERY_RESULT, &stamps[0]);
        glGetQueryObjectui64v(spanQueries[1], GL_QUERY_RESULT, &stamps[1]);
        if (f < 0)
        {
          continue;
        }
        const double measured[Measured] = {
          std::chrono::duration<double, std::milli>(finished - start).count(),
          std::chrono::duration<double, std::milli>(returned - start).count(),
          1e-6 * static_cast<double>(stamps[1] - stamps[0]) };
        csv << sequence->Name << (timed ? ",timed," : ",untimed,") << f;
        for (int m = 0; m < Measured; ++m)
        {
          csv << "," << measured[m];
          if (!timed)
          {
            columns[m].push_back(measured[m]);
          }
        }
        std::string ran;
        for (int s = 0; s < vtkVoxelGIPass::NUMBER_OF_STAGES; ++s)
        {
          csv << "," << (timed ? gi->GetStageTime(s) : 0.0);
          if (timed)
          {
            columns[s + Measured].push_back(gi->GetStageTime(s));
          }
          if (gi->GetStageRan(s))
          {
            ran += std::string(ran.empty() ? "" : "|") + vtkVoxelGIPass::GetStageName(s);
          }
        }
        csv << "," << ran << "\n";
      }
      const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
      ++runsDone;
      std::cerr << "[" << runsDone << "/" << runs << "] " << sequence->Name
                << (timed ? " with stage timers" : "") << ": " << std::fixed
                << std::setprecision(1) << elapsed << " s so far, about "
                << elapsed / runsDone * (runs - runsDone) << " s left" << std::endl;
    }
    sequence->Setup(false);
  }
  glDeleteQueries(2, spanQueries);
  unsigned long long voxelBytes = 0;
  for (vtkVoxelGIPass* pass : passes)
  {
    voxelBytes += pass->GetVoxelMemoryBytes();
  }

  std::ofstream json(o.JSON);
  json << "{\n  \"scene\": \"" << o.Scene << "\", \"actors\": " << actors.size()
       << ", \"triangles\": " << triangles << ", \"width\": " << o.Width
       << ", \"height\": " << o.Height << ", \"resolution\": " << o.Resolution
       << ", \"trace_scale\": " << o.TraceScale
       << ", \"max_trace_megapixels\": " << gi->GetMaxTraceMegapixels()
       << ", \"temporal_reuse\": " << o.TemporalReuse
       << ", \"multisamples\": " << window->GetMultiSamples() << ", \"bounces\": "
       << gi->GetBounces() << ", \"update_interval\": " << o.UpdateInterval
       << ", \"frames\": " << o.Frames << ", \"viewports\": " << o.Viewports
       << ", \"shared_grid\": " << (o.SharedGrid ? "true" : "false")
       << ", \"voxel_memory_bytes\": " << voxelBytes << ", \"software_profile\": "
       << (gi->GetSoftwareProfileActive() ? "true" : "false") << ", \"settings\": {";
  for (size_t i = 0; i < o.Settings.size(); ++i)
  {
    json << (i ? ", " : "") << "\"" << o.Settings[i].first << "\": " << o.Settings[i].second;
  }
  // The date: docs/benchmarks/numbers.py shows the newest measurement of each scene.
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  json << "},\n  \"date\": \"" << date << "\",\n  \"renderer\": \"" << RendererName(window)
       << "\",\n  \"median_ms\": {\n";
  std::cout << std::fixed << std::setprecision(2) << "\nmedian ms on " << RendererName(window)
            << ", " << o.Scene << " (" << actors.size() << " actors, " << triangles
            << " triangles) " << o.Width << "x" << o.Height << ", " << o.Resolution
            << "^3 voxels, trace at " << o.TraceScale << " (halved above "
            << gi->GetMaxTraceMegapixels() << " megapixels)"
            << (gi->GetSoftwareProfileActive() ? " (capped by the software profile)" : "") << ", " << window->GetMultiSamples()
            << "x MSAA, " << o.Frames << " frames, " << o.Viewports << " viewport(s)"
            << (o.SharedGrid ? " sharing one grid" : "") << ", voxel memory "
            << voxelBytes / (1024 * 1024) << " MiB\n"
            << std::setw(16) << "sequence" << std::setw(10) << "mean" << std::setw(10) << "frame" << std::setw(10) << "cpu"
            << std::setw(10) << "gpu span";
  for (int s = 0; s < vtkVoxelGIPass::NUMBER_OF_STAGES; ++s)
  {
    std::cout << std::setw(10) << std::string(vtkVoxelGIPass::GetStageName(s)).substr(0, 9);
  }
  std::cout << "\n";
  for (std::size_t q = 0; q < selected.size(); ++q)
  {
    const std::string& name = selected[q]->Name;
    const auto& columns = samples[name];
    json << "    \"" << name << "\": {\"frame\": " << Median(columns[0])
         << ", \"cpu\": " << Median(columns[1]) << ", \"gpu_span\": " << Median(columns[2])
         << ", \"frame_mean\": " << Mean(columns[0]);
    std::cout << std::setw(16) << name << std::setw(10) << Mean(columns[0]);
    for (int m = 0; m < Measured; ++m)
    {
      std::cout << std::setw(10) << Median(columns[m]);
    }
    for (int s = 0; s < vtkVoxelGIPass::NUMBER_OF_STAGES; ++s)
    {
      json << ", \"" << vtkVoxelGIPass::GetStageName(s) << "\": " << Median(columns[s + Measured]);
      std::cout << std::setw(10) << Median(columns[s + Measured]);
    }
    json << "}" << (q + 1 < selected.size() ? "," : "") << "\n";
    std::cout << "\n";
  }
  json << "  }\n}\n";
  std::cout << "wrote " << o.CSV << " and " << o.JSON << std::endl;
  return EXIT_SUCCESS;
}
