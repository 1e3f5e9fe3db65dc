// Soak: 400 frames of random changes at a small size. Each frame changes one or two things
// at random (seeded): a setting by name (in range, beyond it, or NaN), an actor's position
// or colour, an emissive prop, an added or removed actor, the light, the camera, the
// window's size. Every frame the pass shows a bounded, finite image (and finite radiance),
// the GL memory it holds in GI frames stays within what its settings need, and the process's resident
// memory does not grow once the shader variants have been built (frames 200 to 400).
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"
#include "vtkVoxelGISettings.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace
{
/// The process's resident memory in MiB (VmRSS).
double ResidentMiB()
{
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key)
  {
    if (key == "VmRSS:")
    {
      double kib = 0.0;
      status >> kib;
      return kib / 1024.0;
    }
  }
  return 0.0;
}

/// A value for setting `i`: mostly inside its range, sometimes beyond it or NaN. Voxel and
/// shadow-map resolutions and bounces stay small so that the soak stays quick (64^3 voxels
/// with 7 bounces take 5 s a frame on llvmpipe).
double RandomValue(int i, std::mt19937& random)
{
  const std::string name = vtkVoxelGISettings::GetName(i);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  if (name == "VoxelResolution")
  {
    return unit(random) < 0.5 ? 16 : 32;
  }
  if (name == "Bounces")
  {
    return static_cast<int>(unit(random) * 3); // 0, 1, 2
  }
  if (name == "ShadowMapResolution")
  {
    return unit(random) < 0.5 ? 128 : 256;
  }
  const double draw = unit(random);
  if (draw < 0.05)
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  if (std::string(vtkVoxelGISettings::GetType(i)) == "bool")
  {
    return draw < 0.5 ? 0.0 : 1.0;
  }
  const double lo = vtkVoxelGISettings::GetMinimum(i);
  const double hi = vtkVoxelGISettings::GetMaximum(i);
  // 20 % beyond each end of the range
  return lo + (hi - lo) * (1.4 * unit(random) - 0.2);
}
}

int TestGISoak(int, char*[])
{
  vtkNew<vtkRenderer> renderer;
  voxelgi_test::GIWindow view(renderer, 32, 64);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  vtkVoxelGIScenes::AddCornellBox(renderer);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetPosition(0.5, 0.9, 0.5);
  renderer->AddLight(light);
  // The pass's warnings (clamped and NaN settings) are expected: count them, quietly.
  int messages = 0;
  vtkNew<vtkCallbackCommand> counter;
  counter->SetClientData(&messages);
  counter->SetCallback(
    [](vtkObject*, unsigned long, void* client, void*) { ++*static_cast<int*>(client); });
  gi->AddObserver(vtkCommand::WarningEvent, counter);
  gi->AddObserver(vtkCommand::ErrorEvent, counter);
  renderer->ResetCamera();

  std::mt19937 random(20261202);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<vtkActor*> added;
  const int frames = 400;
  double residentAt200 = 0.0;
  double largestGrowth = 0.0;
  int active = 0;
  for (int frame = 0; frame < frames; ++frame)
  {
    const int changes = 1 + static_cast<int>(unit(random) * 2);
    for (int c = 0; c < changes; ++c)
    {
      switch (static_cast<int>(unit(random) * 8))
      {
        case 0:
        case 1:
        {
          const int i =
            static_cast<int>(unit(random) * vtkVoxelGISettings::GetNumberOfSettings());
          vtkVoxelGISettings::SetValue(gi, vtkVoxelGISettings::GetName(i), RandomValue(i, random));
          break;
        }
        case 2:
          if (added.size() < 6)
          {
            vtkNew<vtkSphereSource> sphere;
            sphere->SetCenter(unit(random), 0.2 + 0.6 * unit(random), unit(random));
            sphere->SetRadius(0.05 + 0.1 * unit(random));
            added.push_back(vtkVoxelGIScenes::AddSource(
              renderer, sphere, unit(random), unit(random), unit(random)));
          }
          break;
        case 3:
          if (!added.empty())
          {
            renderer->RemoveActor(added.back());
            added.pop_back();
          }
          break;
        case 4:
          if (!added.empty())
          {
            vtkActor* actor = added[static_cast<std::size_t>(unit(random) * added.size())];
            actor->SetPosition(0.2 * unit(random) - 0.1, 0.2 * unit(random) - 0.1, 0.0);
            actor->GetProperty()->SetColor(unit(random), unit(random), unit(random));
            if (unit(random) < 0.3)
            {
              vtkVoxelGIPass::SetPropEmission(actor, 2 * unit(random), unit(random), 0.0);
            }
          }
          break;
        case 5:
          light->SetPosition(unit(random), 0.5 + 0.45 * unit(random), unit(random));
          light->SetIntensity(unit(random) < 0.1 ? 0.0 : unit(random));
          break;
        case 6:
          renderer->GetActiveCamera()->Azimuth(30.0 * unit(random) - 15.0);
          break;
        default:
          window->SetSize(48 + static_cast<int>(unit(random) * 48),
            48 + static_cast<int>(unit(random) * 48));
          break;
      }
    }
    window->Render();
    active += gi->GetGIActive() ? 1 : 0;
    VOXELGI_CHECK(!gi->GetGIActive() || voxelgi_test::Bounded(gi),
      "frame " << frame << ": unbounded or non-finite values");
    const unsigned long long held = gi->GetVoxelMemoryBytes();
    // (with GI off the volumes of the last GI frame are kept for the next)
    VOXELGI_CHECK(!gi->GetGIActive() || held <= gi->GetRequiredVoxelMemoryBytes(true),
      "frame " << frame << ": holds " << held << " bytes, its settings need at most "
               << gi->GetRequiredVoxelMemoryBytes(true));
    const double resident = ResidentMiB();
    if (frame == 200)
    {
      residentAt200 = resident;
    }
    else if (frame > 200)
    {
      largestGrowth = std::max(largestGrowth, resident - residentAt200);
    }
  }
  std::cout << frames << " frames, GI active in " << active << ", " << messages
            << " messages; resident memory at frame 200 " << residentAt200
            << " MiB, largest growth after it " << largestGrowth << " MiB" << std::endl;
  VOXELGI_CHECK(active > frames / 4, "GI ran in too few frames to soak anything");
  VOXELGI_CHECK(largestGrowth < 32.0, "resident memory grew by " << largestGrowth << " MiB");
  return EXIT_SUCCESS;
}
