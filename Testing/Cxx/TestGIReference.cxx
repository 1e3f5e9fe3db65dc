// Error against the path-traced references (Blender Cycles, Testing/Reference and
// Testing/Data/Reference/SCENE.pfm), one scene per run:
//
//   TestGIReference SCENE     (CTest runs each as VoxelGI::Reference.SCENE)
//
// Renders plain VTK and the pass at its defaults at the reference's size and prints RMSE,
// relMSE, SSIM, FLIP and the mean radiance of both. The goals (FLIP at most 0.30 in closed
// rooms and 0.12 in open scenes and below plain VTK's, mean radiance within 10 % of the
// reference, RMSE at most half of plain VTK's) are printed as met or "GOAL NOT MET"; where
// they are not met the test asserts the bound the pass meets today (docs/reference.md lists
// the numbers), so that nothing gets worse unnoticed. The software profile
// (vtkVoxelGIPass::SoftwareProfile) is measured too: its FLIP must stay below plain VTK's.
#include "ImageMetrics.h"
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolumeCollection.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>

namespace
{
using voxelgi_test::Within;
struct Bounds
{
  double FlipGoal;  // FLIP goal of the scene
  double Flip;      // FLIP asserted today
  double FlipRatio; // FLIP / plain VTK's FLIP asserted today (goal 1: closer than VTK)
  double Mean;      // |mean / reference mean - 1| asserted today (goal 0.1)
  double RmseRatio; // RMSE / plain VTK's RMSE asserted today (goal 0.5)
};

// Asserted bounds: the goal where it is met, else the llvmpipe measurement
// (docs/reference.md) plus a small margin. Every scene meets every goal today but the
// volume slab's FLIP.
const std::map<std::string, Bounds>& SceneBounds()
{
  static const std::map<std::string, Bounds> bounds = {
    { "cornell", { 0.30, 0.30, 1.0, 0.10, 0.50 } },
    { "glossy", { 0.30, 0.30, 1.0, 0.10, 0.50 } },
    { "isosurface", { 0.30, 0.30, 1.0, 0.10, 0.50 } },
    { "glyphs", { 0.12, 0.12, 1.0, 0.10, 0.50 } },
    { "emissive", { 0.30, 0.30, 1.0, 0.10, 0.50 } },
    { "streamlines", { 0.12, 0.12, 1.0, 0.10, 0.50 } },
    { "volume", { 0.12, 0.16, 1.0, 0.10, 0.50 } }, // measured FLIP 0.149
  };
  return bounds;
}

struct Score
{
  voxelgi::metrics::Errors Errors;
  double Mean = 0.0;
};

Score Measure(vtkFloatArray* rgba, const voxelgi::metrics::Image& reference, const char* label)
{
  const voxelgi::metrics::Image image =
    voxelgi::metrics::FromRgba(rgba->GetPointer(0), reference.Width, reference.Height);
  Score s;
  s.Errors = voxelgi::metrics::Compare(image, reference);
  double sum = 0.0;
  for (float v : image.Rgb)
  {
    sum += v;
  }
  s.Mean = sum / static_cast<double>(image.Rgb.size());
  std::cout << label << ": RMSE " << s.Errors.Rmse << ", relMSE " << s.Errors.RelMse
            << ", SSIM " << s.Errors.Ssim << ", FLIP " << s.Errors.Flip << ", mean radiance "
            << s.Mean << "\n";
  return s;
}
}

int TestGIReference(int argc, char* argv[])
{
  // The test driver passes the test name first; the scene follows (default: the Cornell box).
  std::string scene = "cornell";
  for (int i = 1; i < argc; ++i)
  {
    if (SceneBounds().count(argv[i]))
    {
      scene = argv[i];
    }
  }
  const Bounds& bounds = SceneBounds().at(scene);
  voxelgi::metrics::Image reference;
  const std::string path = std::string(VOXELGI_TEST_DATA_DIR) + "/Reference/" + scene + ".pfm";
  VOXELGI_CHECK(voxelgi::metrics::ReadPfm(path, reference), "cannot read " << path);
  const int w = reference.Width, h = reference.Height;
  double referenceMean = 0.0;
  for (float v : reference.Rgb)
  {
    referenceMean += v;
  }
  referenceMean /= static_cast<double>(reference.Rgb.size());
  std::cout << scene << ": reference mean radiance " << referenceMean << std::endl;

  vtkNew<vtkRenderer> renderer;
  VOXELGI_CHECK(vtkVoxelGIScenes::AddScene(renderer, scene.c_str()), "no scene " << scene);
  voxelgi_test::GIWindow view(renderer, 0); // the pass's defaults
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  window->SetSize(w, h); // the reference's
  view.RenderWithoutGI();
  vtkNew<vtkFloatArray> plainPixels;
  window->GetRGBAPixelData(0, 0, w - 1, h - 1, 0, plainPixels);
  const Score plain = Measure(plainPixels, reference, "plain VTK");

  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
  VOXELGI_CHECK(voxelgi_test::AllFinite(gi), "non-finite values");
  // VTK draws volumes over the composite: where the scene has one, the window's image is what
  // the reference shows.
  const bool volumes = renderer->GetVolumes()->GetNumberOfItems() > 0;
  auto image = [&](vtkFloatArray* pixels) {
    if (volumes)
    {
      window->GetRGBAPixelData(0, 0, w - 1, h - 1, 0, pixels);
      return true;
    }
    return gi->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, pixels);
  };
  vtkNew<vtkFloatArray> giPixels;
  VOXELGI_CHECK(image(giPixels), "no image");
  const Score withGI = Measure(giPixels, reference, "voxel GI (defaults)");

  bool ok = Within(scene + ", FLIP", withGI.Errors.Flip, bounds.FlipGoal, bounds.Flip);
  ok = Within(scene + ", FLIP relative to plain VTK's", withGI.Errors.Flip / plain.Errors.Flip,
         1.0, bounds.FlipRatio) &&
    ok;
  ok = Within(scene + ", error of the mean radiance", std::abs(withGI.Mean / referenceMean - 1.0),
         0.1, bounds.Mean) &&
    ok;
  ok = Within(scene + ", RMSE relative to plain VTK's", withGI.Errors.Rmse / plain.Errors.Rmse,
         0.5, bounds.RmseRatio) &&
    ok;

  gi->SetSoftwareProfileToOn();
  window->Render();
  VOXELGI_CHECK(gi->GetGIActive() && voxelgi_test::AllFinite(gi), "software profile");
  VOXELGI_CHECK(image(giPixels), "no image");
  const Score software = Measure(giPixels, reference, "voxel GI (software profile)");
  ok = Within(scene + ", software profile's FLIP relative to plain VTK's",
         software.Errors.Flip / plain.Errors.Flip, 1.0, 1.0) &&
    ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
