// Error against run time: renders the Cornell box with baselines (plain VTK, VTK's SSAO, the
// pass with GI off) and with the pass at its defaults and with one setting varied at a time,
// and writes, per configuration, the median frame time (full update every frame: voxelize,
// light, mip, trace), the median per-stage GPU times and the error against the path-traced
// reference (RMSE, relMSE, SSIM, FLIP) as CSV.
//
//   VoxelGIErrorStudy REFERENCE.pfm OUT.csv [frames]
#include "ImageMetrics.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"
#include "vtkVoxelGISettings.h"

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSSAOPass.h"

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
  if (argc < 3)
  {
    std::cerr << "usage: VoxelGIErrorStudy REFERENCE.pfm OUT.csv [frames]\n";
    return EXIT_FAILURE;
  }
  voxelgi::metrics::Image reference;
  if (!voxelgi::metrics::ReadPfm(argv[1], reference))
  {
    std::cerr << "cannot read " << argv[1] << "\n";
    return EXIT_FAILURE;
  }
  const int frames = argc > 3 ? std::max(1, std::atoi(argv[3])) : 5;

  std::vector<Config> configs = { { "plain", "", 0 }, { "ssao", "", 0 }, { "gi-off", "", 0 },
    { "defaults", "", 0 } };
  const std::vector<std::pair<std::string, std::vector<double>>> sweep = {
    { "VoxelResolution", { 32, 64, 256 } }, { "DiffuseConeCount", { 1, 3, 9, 16 } },
    { "DiffuseConeAperture", { 30, 45, 90 } }, { "ConeStepFactor", { 0.35, 0.5, 1.0, 1.5 } },
    { "Bounces", { 0, 2 } }, { "TraceResolution", { 0.5, 0.25 } },
    { "AnisotropicMipmaps", { 0 } } };
  for (const auto& s : sweep)
  {
    for (double v : s.second)
    {
      configs.push_back({ s.first, s.first, v });
    }
  }

  std::ofstream csv(argv[2]);
  csv << "config,setting,value,frame_ms,rmse,relmse,ssim,flip";
  for (int s = 0; s < vtkVoxelGIPass::NUMBER_OF_STAGES; ++s)
  {
    csv << "," << vtkVoxelGIPass::GetStageName(s) << "_ms";
  }
  csv << "\n";

  for (const Config& config : configs)
  {
    vtkNew<vtkRenderer> renderer;
    vtkVoxelGIScenes::AddCornellBox(renderer);
    vtkNew<vtkRenderWindow> window;
    window->SetSize(reference.Width, reference.Height);
    window->SetOffScreenRendering(true);
    window->AddRenderer(renderer);
    vtkNew<vtkVoxelGIPass> gi;
    vtkNew<vtkRenderStepsPass> steps;
    vtkNew<vtkSSAOPass> ssao;
    const bool usesPass = config.Name != "plain" && config.Name != "ssao";
    if (config.Name == "ssao")
    {
      // radius and bias in scene units: the box is 5.5 wide
      ssao->SetDelegatePass(steps);
      ssao->SetRadius(0.5);
      ssao->SetBias(0.01);
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

    std::vector<double> frameMs;
    std::vector<std::vector<double>> stageMs(vtkVoxelGIPass::NUMBER_OF_STAGES);
    for (int f = -1; f < frames; ++f) // one warm-up frame
    {
      // a new camera every frame, so that the stored image is never presented again
      renderer->GetActiveCamera()->Azimuth(f % 2 ? 0.01 : -0.01);
      window->WaitForCompletion();
      const auto start = std::chrono::steady_clock::now();
      window->Render();
      window->WaitForCompletion();
      if (f < 0)
      {
        continue;
      }
      frameMs.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      for (int s = 0; usesPass && s < vtkVoxelGIPass::NUMBER_OF_STAGES; ++s)
      {
        stageMs[s].push_back(gi->GetStageRan(s) ? gi->GetStageTime(s) : 0.0);
      }
    }

    vtkNew<vtkFloatArray> pixels;
    if (!(usesPass && gi->GetEnabled() &&
          gi->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, pixels)))
    {
      window->GetRGBAPixelData(0, 0, reference.Width - 1, reference.Height - 1, 0, pixels);
    }
    const voxelgi::metrics::Errors e = voxelgi::metrics::Compare(
      voxelgi::metrics::FromRgba(pixels->GetPointer(0), reference.Width, reference.Height),
      reference);
    csv << config.Name << "," << config.Setting << "," << config.Value << "," << Median(frameMs)
        << "," << e.Rmse << "," << e.RelMse << "," << e.Ssim << "," << e.Flip;
    for (const auto& s : stageMs)
    {
      csv << "," << Median(s);
    }
    csv << "\n";
    std::cout << config.Name << " " << config.Value << ": " << Median(frameMs) << " ms, RMSE "
              << e.Rmse << ", relMSE " << e.RelMse << ", SSIM " << e.Ssim << ", FLIP " << e.Flip
              << std::endl;
  }
  return EXIT_SUCCESS;
}
