// Error against run time: renders one of vtkVoxelGIScenes' scenes, or a scene description
// written by vtkVoxelGISceneFile from any program's renderer, with baselines (plain VTK,
// VTK's SSAO, the pass with GI off) and with the pass at its defaults and with one setting
// varied at a time, and writes, per configuration, the median frame time (full update every
// frame: voxelize, light, mip, trace), the median camera-only frame time (only tracing and
// compositing rerun), the median per-stage GPU times of the full update and the error against
// the path-traced reference (RMSE, relMSE, SSIM, FLIP) as CSV. The images of the plain, ssao
// and defaults configurations are written beside it (OUT-plain.pfm, ...), linear float RGB.
// A scene lit by camera-following lights (a headlight) also gets CameraLightTurn rows: the
// image after an orbit of 92 degrees in 2-degree steps that ends at the scene's camera (the
// voxel light lags as it would for a user), with the orbit's mean frame as camera_ms; the
// lag itself (the error against the defaults' image) is printed. A scene with a scene light
// gets an InteractiveBounces row: the image of the last of 20 frames rendered interactively
// (the window's desired update rate of an interactor style's drag) while the first scene
// light circles by a twentieth of the scene's extent and returns to its place, so that each
// relight bounces once on from the last solution, with the drag's mean frame as camera_ms;
// its error against the defaults' image is printed too.
//
//   VoxelGIErrorStudy [--egl] SCENE REFERENCE.pfm OUT.csv [frames]
//
// SCENE: a name vtkVoxelGIScenes::AddScene knows (cornell, glossy, isosurface, glyphs, emissive,
// streamlines, volume, pointroom, lamproom, emitterroom, contacts, contactsheadlight,
// translucent), or a
// description FILE.json (Testing/Reference/study_scene.sh
// renders its reference and runs this). --egl renders headless through EGL
// (vtkVoxelGIEGLRenderWindow), as on a GPU machine without X.
#include "ImageMetrics.h"
#include "vtkVoxelGIEGLRenderWindow.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGISceneFile.h"
#include "vtkVoxelGIScenes.h"
#include "vtkVoxelGISettings.h"

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSSAOPass.h"
#include "vtkSmartPointer.h"
#include "vtkVolumeCollection.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
struct Config
{
  std::string Name;    // "plain", "ssao", "gi-off", "defaults" or the varied setting
  std::string Setting; // setting of the settings table, empty for the others
  double Value = 0.0;
};

/// Render 20 frames interactively (an interactor style's desired update rate) while the first
/// scene light circles by a twentieth of the scene's extent, ending at its place; returns the
/// mean frame in ms and leaves the last frame unconverged (no still frame after it).
double DragFirstSceneLight(vtkRenderer* renderer, vtkRenderWindow* window)
{
  vtkLight* light = nullptr;
  vtkCollectionSimpleIterator it;
  renderer->GetLights()->InitTraversal(it);
  while (!light)
  {
    vtkLight* candidate = renderer->GetLights()->GetNextLight(it);
    if (!candidate)
    {
      return 0.0;
    }
    light = candidate->GetSwitch() && candidate->LightTypeIsSceneLight() ? candidate : nullptr;
  }
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  const double radius =
    0.05 * std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  double home[3];
  light->GetPosition(home);
  constexpr int Steps = 20;
  const double rate = window->GetDesiredUpdateRate();
  window->SetDesiredUpdateRate(15.0);
  double meanMs = 0.0;
  for (int step = 1; step <= Steps; ++step)
  {
    const double angle = 2.0 * vtkMath::Pi() * step / Steps;
    const double dx = step == Steps ? 0.0 : radius * std::sin(angle);
    const double dz = step == Steps ? 0.0 : radius * (1.0 - std::cos(angle));
    light->SetPosition(home[0] + dx, home[1], home[2] + dz);
    window->WaitForCompletion();
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    window->WaitForCompletion();
    meanMs +=
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() /
      Steps;
  }
  window->SetDesiredUpdateRate(rate);
  return meanMs;
}

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
}

int main(int argc, char* argv[])
{
  bool egl = false;
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i)
  {
    if (std::string(argv[i]) == "--egl")
    {
      egl = true;
    }
    else
    {
      args.emplace_back(argv[i]);
    }
  }
  if (args.size() < 3)
  {
    std::cerr << "usage: VoxelGIErrorStudy [--egl] SCENE REFERENCE.pfm OUT.csv [frames]\n";
    return EXIT_FAILURE;
  }
  const std::string& scene = args[0];
  const bool file = scene.size() > 5 && scene.compare(scene.size() - 5, 5, ".json") == 0;
  auto addScene = [&scene, file](vtkRenderer* renderer) {
    if (!file)
    {
      return vtkVoxelGIScenes::AddScene(renderer, scene.c_str());
    }
    vtkNew<vtkVoxelGISceneFile> description;
    description->SetFileName(scene.c_str());
    return description->Read(renderer);
  };
  bool cameraLights = false;
  bool sceneLights = false;
  {
    vtkNew<vtkRenderer> probe;
    if (!addScene(probe))
    {
      std::cerr << "unknown scene " << scene << "\n";
      return EXIT_FAILURE;
    }
    vtkCollectionSimpleIterator it;
    probe->GetLights()->InitTraversal(it);
    while (vtkLight* light = probe->GetLights()->GetNextLight(it))
    {
      cameraLights = cameraLights || (light->GetSwitch() && !light->LightTypeIsSceneLight());
      sceneLights = sceneLights || (light->GetSwitch() && light->LightTypeIsSceneLight());
    }
    cameraLights = cameraLights ||
      (probe->GetLights()->GetNumberOfItems() == 0 && probe->GetAutomaticLightCreation());
  }
  voxelgi::metrics::Image reference;
  if (!voxelgi::metrics::ReadPfm(args[1], reference))
  {
    std::cerr << "cannot read " << args[1] << "\n";
    return EXIT_FAILURE;
  }
  const int frames = args.size() > 3 ? std::max(1, std::atoi(args[3].c_str())) : 5;

  std::vector<Config> configs = { { "plain", "", 0 }, { "ssao", "", 0 }, { "gi-off", "", 0 },
    { "defaults", "", 0 } };
  const std::vector<std::pair<std::string, std::vector<double>>> sweep = {
    { "VoxelResolution", { 32, 64, 256 } }, { "DiffuseConeCount", { 1, 3, 6, 9 } },
    { "DiffuseConeAperture", { 30, 45, 90 } }, { "ConeStepFactor", { 0.35, 0.5, 1.0, 1.5 } },
    { "Bounces", { 0, 1, 2, 4, 6 } }, { "BounceTail", { 0 } }, { "TraceResolution", { 0.5, 0.25 } },
    { "TemporalReuse", { 0 } },
    { "AnisotropicMipmaps", { 0 } }, { "AmbientOcclusionStrength", { 0, 0.5 } },
    { "SpecularCone", { 0 } }, { "LightOcclusion", { 0, 1 } },
    { "ShadowMapResolution", { 512, 2048 } } };
  constexpr double OrbitStep = 2.0;
  constexpr int OrbitSteps = 46;
  if (cameraLights)
  {
    configs.push_back({ "CameraLightTurn", "CameraLightTurn", 0.0 });
    for (double turn : { 10.0, 30.0, 45.0, 60.0, 90.0 })
    {
      configs.push_back({ "CameraLightTurn", "CameraLightTurn", turn });
    }
  }
  if (sceneLights)
  {
    configs.push_back({ "InteractiveBounces", "InteractiveBounces", 1.0 });
  }
  for (const auto& s : sweep)
  {
    for (double v : s.second)
    {
      configs.push_back({ s.first, s.first, v });
    }
  }

  voxelgi::metrics::Image defaultsImage;
  std::ofstream csv(args[2]);
  csv << "config,setting,value,frame_ms,camera_ms,rmse,relmse,ssim,flip";
  for (int s = 0; s < vtkVoxelGIPass::NUMBER_OF_STAGES; ++s)
  {
    csv << "," << vtkVoxelGIPass::GetStageName(s) << "_ms";
  }
  csv << "\n";

  // Progress on stderr after each configuration: on a software renderer the study takes tens
  // of minutes.
  const auto began = std::chrono::steady_clock::now();
  std::size_t done = 0;
  for (const Config& config : configs)
  {
    vtkNew<vtkRenderer> renderer;
    addScene(renderer);
    vtkSmartPointer<vtkRenderWindow> window = egl
      ? vtkSmartPointer<vtkRenderWindow>(vtkSmartPointer<vtkVoxelGIEGLRenderWindow>::New())
      : vtkSmartPointer<vtkRenderWindow>::New();
    window->SetSize(reference.Width, reference.Height);
    window->SetOffScreenRendering(true);
    window->AddRenderer(renderer);
    vtkNew<vtkVoxelGIPass> gi;
    gi->SetSoftwareProfileToOff(); // the settings themselves, also on a CPU renderer
    vtkNew<vtkRenderStepsPass> steps;
    vtkNew<vtkSSAOPass> ssao;
    const bool usesPass = config.Name != "plain" && config.Name != "ssao";
    if (config.Name == "ssao")
    {
      // radius and bias in scene units: a tenth and a five-hundredth of the scene's extent
      double bounds[6];
      renderer->ComputeVisiblePropBounds(bounds);
      const double extent =
        std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
      ssao->SetDelegatePass(steps);
      ssao->SetRadius(0.1 * extent);
      ssao->SetBias(0.002 * extent);
      ssao->SetKernelSize(128);
      renderer->SetPass(ssao);
    }
    else if (usesPass)
    {
      gi->SetEnabled(config.Name != "gi-off");
      gi->SetUpdatePolicy(vtkVoxelGIPass::UPDATE_EVERY_FRAME);
      gi->TimeStagesOn();
      if (!config.Setting.empty())
      {
        vtkVoxelGISettings::SetValue(gi, config.Setting.c_str(), config.Value);
      }
      renderer->SetPass(gi);
    }

    // Frames with a new camera each (so that no stored image is presented again), after one
    // warm-up frame; returns their wall-clock times and records the stage times if asked.
    std::vector<std::vector<double>> stageMs(vtkVoxelGIPass::NUMBER_OF_STAGES);
    auto timeFrames = [&](bool recordStages) {
      std::vector<double> ms;
      for (int f = -1; f < frames; ++f)
      {
        renderer->GetActiveCamera()->Azimuth(f % 2 ? 0.01 : -0.01);
        window->WaitForCompletion();
        const auto start = std::chrono::steady_clock::now();
        window->Render();
        window->WaitForCompletion();
        if (f < 0)
        {
          continue;
        }
        ms.push_back(std::chrono::duration<double, std::milli>(
          std::chrono::steady_clock::now() - start)
                       .count());
        for (int s = 0; recordStages && usesPass && s < vtkVoxelGIPass::NUMBER_OF_STAGES; ++s)
        {
          stageMs[s].push_back(gi->GetStageRan(s) ? gi->GetStageTime(s) : 0.0);
        }
      }
      return Median(ms);
    };
    const double frameMs = timeFrames(true);
    // Only the camera moves from now on: the pass reruns tracing and compositing alone.
    gi->SetUpdatePolicy(vtkVoxelGIPass::UPDATE_ON_CHANGE);
    double cameraMs = 0.0;
    if (config.Setting == "CameraLightTurn")
    {
      renderer->GetActiveCamera()->Azimuth(-OrbitStep * OrbitSteps);
      window->Render();
      for (int step = 0; step < OrbitSteps; ++step)
      {
        renderer->GetActiveCamera()->Azimuth(OrbitStep);
        window->WaitForCompletion();
        const auto start = std::chrono::steady_clock::now();
        window->Render();
        window->WaitForCompletion();
        cameraMs += std::chrono::duration<double, std::milli>(
          std::chrono::steady_clock::now() - start).count() / OrbitSteps;
      }
    }
    else if (config.Setting == "InteractiveBounces")
    {
      cameraMs = DragFirstSceneLight(renderer, window);
    }
    else
    {
      cameraMs = timeFrames(false);
    }

    // VTK draws volumes and translucent actors over the composite: then the window's image
    // is what the reference shows.
    vtkNew<vtkFloatArray> pixels;
    if (vtkVoxelGIScenes::DrawsOverComposite(renderer) ||
      !(usesPass && gi->GetEnabled() &&
        gi->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, pixels)))
    {
      window->GetRGBAPixelData(0, 0, reference.Width - 1, reference.Height - 1, 0, pixels);
    }
    const voxelgi::metrics::Image image =
      voxelgi::metrics::FromRgba(pixels->GetPointer(0), reference.Width, reference.Height);
    const voxelgi::metrics::Errors e = voxelgi::metrics::Compare(image, reference);
    if (config.Name == "defaults")
    {
      defaultsImage = image;
    }
    if ((config.Setting == "CameraLightTurn" || config.Setting == "InteractiveBounces") &&
      defaultsImage.Width == image.Width)
    {
      const voxelgi::metrics::Errors lag = voxelgi::metrics::Compare(image, defaultsImage);
      std::cout << config.Setting << " " << config.Value
                << " after the orbit or drag, against the defaults: RMSE " << lag.Rmse
                << ", FLIP " << lag.Flip << std::endl;
    }
    if (config.Name == "plain" || config.Name == "ssao" || config.Name == "defaults")
    {
      const std::string& out = args[2];
      const std::string stem = out.size() > 4 && out.compare(out.size() - 4, 4, ".csv") == 0
        ? out.substr(0, out.size() - 4)
        : out;
      voxelgi::metrics::WritePfm(stem + "-" + config.Name + ".pfm", image);
    }
    csv << config.Name << "," << config.Setting << "," << config.Value << "," << frameMs << ","
        << cameraMs << "," << e.Rmse << "," << e.RelMse << "," << e.Ssim << "," << e.Flip;
    for (const auto& s : stageMs)
    {
      csv << "," << Median(s);
    }
    csv << "\n";
    std::cout << config.Name << " " << config.Value << ": " << frameMs << " ms (camera only "
              << cameraMs << " ms), RMSE "
              << e.Rmse << ", relMSE " << e.RelMse << ", SSIM " << e.Ssim << ", FLIP " << e.Flip
              << std::endl;
    const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    ++done;
    std::cerr << "[" << done << "/" << configs.size() << "] " << static_cast<long>(elapsed)
              << " s so far, about "
              << static_cast<long>(elapsed / done * (configs.size() - done)) << " s left"
              << std::endl;
  }
  return EXIT_SUCCESS;
}
