// Error against the path-traced references (Blender Cycles, Testing/Reference and
// Testing/Data/Reference/SCENE.pfm), one scene per run:
//
//   TestGIReference SCENE     (CTest runs each as VoxelGI::Reference.SCENE)
//
//   TestGIReference SCENE-orders   (VoxelGI::Reference.SCENE-orders: the pass order by order,
//                                   Orders() below)
//
//   TestGIReference SCENE-emitters (VoxelGI::Reference.SCENE-emitters: the pixels' gather of
//                                   the emitters, EmitterGather() below)
//
// Renders plain VTK and the pass at its defaults at the reference's size and prints RMSE,
// relMSE, SSIM, FLIP and the mean radiance of both. The goals (FLIP at most 0.20 in closed
// rooms and 0.12 in open scenes and at most 0.6 of plain VTK's, mean radiance within 10 % of
// the reference, RMSE at most half of plain VTK's) are printed as met or "GOAL NOT MET"; where
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
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"

#include <algorithm>
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
  double FlipGoal;  // FLIP goal of the scene: 0.20 in closed rooms, 0.12 in open scenes
  double Flip;      // FLIP asserted today
  double FlipRatio; // FLIP / plain VTK's FLIP asserted today (goal 0.6)
  double Mean;      // |mean / reference mean - 1| asserted today (goal 0.1)
  double RmseRatio; // RMSE / plain VTK's RMSE asserted today (goal 0.5)
};

// Asserted bounds: the goal where it is met, else the llvmpipe measurement
// (docs/reference.md) plus a small margin.
const std::map<std::string, Bounds>& SceneBounds()
{
  static const std::map<std::string, Bounds> bounds = {
    { "cornell", { 0.20, 0.20, 0.6, 0.10, 0.50 } },
    { "glossy", { 0.20, 0.20, 0.6, 0.10, 0.50 } },
    { "isosurface", { 0.20, 0.25, 0.6, 0.10, 0.50 } }, // measured FLIP 0.2451
    { "glyphs", { 0.12, 0.125, 0.6, 0.10, 0.50 } }, // measured FLIP 0.1198
    { "emissive", { 0.20, 0.205, 0.6, 0.10, 0.50 } }, // measured FLIP 0.1993, mean -9.1 %
    { "streamlines", { 0.12, 0.12, 0.6, 0.10, 0.50 } },
    { "volume", { 0.12, 0.12, 0.6, 0.10, 0.50 } },
    // Scenes nobody tuned the pass to (issue 36).
    { "pointroom", { 0.20, 0.20, 0.6, 0.10, 0.50 } },
    { "lamproom", { 0.20, 0.20, 0.6, 0.10, 0.50 } },
    { "emitterroom", { 0.20, 0.21, 0.6, 0.10, 0.50 } }, // measured FLIP 0.202, mean +9.3 %
    { "volumeroom", { 0.20, 0.20, 0.6, 0.10, 0.50 } },
    { "contacts", { 0.12, 0.12, 0.6, 0.10, 0.50 } },
    { "contactsheadlight", { 0.12, 0.12, 0.6, 0.10, 0.66 } }, // measured RMSE ratio 0.599
    // Translucent surfaces' shadows (issue 34).
    { "translucent", { 0.12, 0.12, 0.6, 0.10, 0.50 } },
  };
  return bounds;
}

// The contact scenes (vtkVoxelGIScenes::AddContacts): the floor just in front of the three
// spheres' contacts against the open floor, and the floor-wall seam against the faces it
// joins, as the mean of 3 x 3 pixels around each point's projection.
struct Contacts
{
  double Ring = 0.0;      // floor 0.1 in front of the contacts
  double OpenFloor = 0.0; // floor far from every object
  double Seam = 0.0;      // the brighter of the floor and the wall next to the seam
  double Faces = 0.0;     // the brighter of the floor and the wall 0.25-0.3 from the seam
};

Contacts ProbeContacts(const voxelgi::metrics::Image& image, vtkRenderer* renderer)
{
  auto at = [&](double x, double y, double z) {
    renderer->SetWorldPoint(x, y, z, 1.0);
    renderer->WorldToDisplay();
    const double* d = renderer->GetDisplayPoint();
    const int px = static_cast<int>(std::lround(d[0] - 0.5));
    const int py = static_cast<int>(std::lround(d[1] - 0.5));
    double sum = 0.0;
    for (int j = py - 1; j <= py + 1; ++j)
    {
      for (int i = px - 1; i <= px + 1; ++i)
      {
        for (int c = 0; c < 3; ++c)
        {
          sum += image.Rgb[3 * (static_cast<size_t>(j) * image.Width + i) + c];
        }
      }
    }
    return sum / 27.0;
  };
  Contacts c;
  for (int i = 0; i < 3; ++i)
  {
    c.Ring += at(-0.6 + 1.2 * i, 0.0, 0.7) / 3.0;
  }
  for (double x : { -3.0, -1.5, 0.0 })
  {
    c.OpenFloor += at(x, 0.0, 3.5) / 3.0;
  }
  c.Seam = std::max(at(-1.9, 0.0, -2.95), at(-1.9, 0.05, -3.0));
  c.Faces = std::max(at(-1.9, 0.0, -2.75), at(-1.9, 0.3, -3.0));
  return c;
}

// Contacts darken where the reference darkens them (the ring's ratio to the open floor within
// 0.1 of the reference's), and no seam is brighter than both faces it joins. `seamExcess`:
// the seam's excess asserted today.
bool ContactsHold(const std::string& scene, vtkRenderer* renderer,
  const voxelgi::metrics::Image& image, const voxelgi::metrics::Image& reference,
  double seamExcess)
{
  const Contacts gi = ProbeContacts(image, renderer);
  const Contacts truth = ProbeContacts(reference, renderer);
  const double ratio = gi.Ring / gi.OpenFloor, truthRatio = truth.Ring / truth.OpenFloor;
  std::cout << scene << ": contact ring / open floor " << ratio << " (reference " << truthRatio
            << "); seam " << gi.Seam << ", faces " << gi.Faces << " (reference " << truth.Seam
            << ", " << truth.Faces << ")\n";
  bool ok = Within(scene + ", contact ring / open floor off the reference's",
    std::abs(ratio - truthRatio), 0.1, 0.1);
  if (truthRatio < 1.0)
  {
    ok = Within(scene + ", contact ring / open floor (darker, as in the reference)", ratio, 1.0,
           1.0) &&
      ok;
  }
  return Within(scene + ", seam above the brighter face it joins", gi.Seam - gi.Faces, 0.0,
           seamExcess) &&
    ok;
}

// The mean radiance of `image` over the middle three fifths of the volume's face toward +z
// (vtkVoxelGIScenes::AddVolumeRoom: the camera looks down -z at it), clamped to [0, 1] as the
// window that VTK draws the volume into holds it (and as FLIP reads it).
double VolumeFaceMean(const voxelgi::metrics::Image& image, vtkRenderer* renderer)
{
  vtkVolumeCollection* volumes = renderer->GetVolumes();
  volumes->InitTraversal();
  const double* b = volumes->GetNextVolume()->GetBounds();
  int lo[2] = { image.Width, image.Height }, hi[2] = { 0, 0 };
  for (double u : { 0.2, 0.8 })
  {
    for (double v : { 0.2, 0.8 })
    {
      renderer->SetWorldPoint(b[0] + u * (b[1] - b[0]), b[2] + v * (b[3] - b[2]), b[5], 1.0);
      renderer->WorldToDisplay();
      const double* d = renderer->GetDisplayPoint();
      for (int k = 0; k < 2; ++k)
      {
        lo[k] = std::min(lo[k], static_cast<int>(d[k]));
        hi[k] = std::max(hi[k], static_cast<int>(d[k]));
      }
    }
  }
  double sum = 0.0;
  for (int j = std::max(lo[1], 0); j <= std::min(hi[1], image.Height - 1); ++j)
  {
    for (int i = std::max(lo[0], 0); i <= std::min(hi[0], image.Width - 1); ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        sum += std::min(1.f, image.Rgb[3 * (static_cast<size_t>(j) * image.Width + i) + c]);
      }
    }
  }
  return sum / (3.0 * (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1));
}

// A volume in a closed room lit by an emitter gains the light it scatters: over its face,
// GI must add to its unlit image (no indirect light, no specular cone) what the reference
// shows over that image, within 10 % (the unlit image equals Cycles' camera-only emission,
// render_cycles.py). `giImage`: the window's image with GI at the defaults.
bool VolumeLitByRoom(voxelgi_test::GIWindow& view, vtkRenderer* renderer,
  const voxelgi::metrics::Image& giImage, const voxelgi::metrics::Image& reference)
{
  vtkVoxelGIPass* gi = view.GI;
  gi->SetIndirectIntensity(0.0);
  gi->SetSpecularCone(false);
  view.Window->Render();
  vtkNew<vtkFloatArray> pixels;
  view.Window->GetRGBAPixelData(0, 0, reference.Width - 1, reference.Height - 1, 0, pixels);
  gi->SetIndirectIntensity(1.0);
  gi->SetSpecularCone(true);
  const double unlit = VolumeFaceMean(
    voxelgi::metrics::FromRgba(pixels->GetPointer(0), reference.Width, reference.Height),
    renderer);
  const double lit = VolumeFaceMean(giImage, renderer);
  const double truth = VolumeFaceMean(reference, renderer);
  const double share = (lit - unlit) / (truth - unlit);
  std::cout << "volume's face: unlit " << unlit << ", with GI " << lit << ", reference "
            << truth << ": GI adds " << share << " of the reference's gain\n";
  return Within("volume's gain from the room off the reference's", std::abs(share - 1.0), 0.1,
    0.1);
}

struct Score
{
  voxelgi::metrics::Errors Errors;
  double Mean = 0.0;
};

double MeanOf(const voxelgi::metrics::Image& image)
{
  double sum = 0.0;
  for (float v : image.Rgb)
  {
    sum += v;
  }
  return sum / static_cast<double>(image.Rgb.size());
}

Score Measure(vtkFloatArray* rgba, const voxelgi::metrics::Image& reference, const char* label)
{
  const voxelgi::metrics::Image image =
    voxelgi::metrics::FromRgba(rgba->GetPointer(0), reference.Width, reference.Height);
  Score s;
  s.Errors = voxelgi::metrics::Compare(image, reference);
  s.Mean = MeanOf(image);
  std::cout << label << ": RMSE " << s.Errors.Rmse << ", relMSE " << s.Errors.RelMse
            << ", SSIM " << s.Errors.Ssim << ", FLIP " << s.Errors.Flip << ", mean radiance "
            << s.Mean << "\n";
  return s;
}

bool ReadReference(const std::string& name, voxelgi::metrics::Image& image)
{
  const std::string path = std::string(VOXELGI_TEST_DATA_DIR) + "/Reference/" + name + ".pfm";
  if (!voxelgi::metrics::ReadPfm(path, image))
  {
    std::cerr << "ERROR: cannot read " << path << std::endl;
    return false;
  }
  return true;
}

// A built-in scene in a window of a reference's size, the pass at its defaults.
struct SceneWindow
{
  SceneWindow(const std::string& scene, int width, int height)
    : Added(vtkVoxelGIScenes::AddScene(this->Renderer, scene.c_str()))
    , View(this->Renderer, 0)
  {
    this->View.Window->SetSize(width, height);
  }
  /// Render and copy the pass's composite: false where GI did not run or left non-finite
  /// values.
  bool Composite(vtkFloatArray* pixels)
  {
    this->View.Window->Render();
    return this->View.GI->GetGIActive() &&
      this->View.GI->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, pixels) &&
      voxelgi_test::AllFinite(this->View.GI);
  }
  vtkNew<vtkRenderer> Renderer;
  bool Added;
  voxelgi_test::GIWindow View;
};

// The share of the first bounce asserted today per scene with order references (goal 0.95).
const std::map<std::string, double>& FirstBounceBounds()
{
  static const std::map<std::string, double> bounds = {
    { "pointroom", 0.95 }, // measured 1.032
    { "lamproom", 0.93 },  // measured 0.942
  };
  return bounds;
}

// The pass order by order against Cycles renders whose paths stop after 0 and 1 bounces
// (SCENE-b0.pfm, SCENE-b1.pfm: make_reference.sh SCENE SAMPLES BOUNCES). The direct light
// alone (no indirect light, no specular cone) must agree with the 0-bounce render within 2 %
// of its mean, so that the comparisons measure GI alone; `Bounces` 0 without the tail (the
// pixels' own gather of the voxels' direct light) must add the first bounce, the mean of the
// 1-bounce render less the 0-bounce one's, within 5 % (docs/reference.md).
int Orders(const std::string& scene)
{
  voxelgi::metrics::Image direct, first;
  VOXELGI_CHECK(ReadReference(scene + "-b0", direct) && ReadReference(scene + "-b1", first),
    "no order references");
  SceneWindow window(scene, direct.Width, direct.Height);
  VOXELGI_CHECK(window.Added, "no scene " << scene);
  vtkVoxelGIPass* gi = window.View.GI;
  gi->SetIndirectIntensity(0.0);
  gi->SetSpecularCone(false);
  vtkNew<vtkFloatArray> pixels;
  VOXELGI_CHECK(window.Composite(pixels), "GI did not run");
  const double directMean = Measure(pixels, direct, "direct light alone").Mean;
  gi->SetIndirectIntensity(1.0);
  gi->SetSpecularCone(true);
  gi->SetBounces(0);
  gi->SetBounceTail(false);
  VOXELGI_CHECK(window.Composite(pixels), "GI did not run");
  const double firstMean = Measure(pixels, first, "direct light and the first bounce").Mean;
  const double share = (firstMean - directMean) / (MeanOf(first) - MeanOf(direct));
  std::cout << scene << ": direct light " << directMean / MeanOf(direct)
            << " of the 0-bounce render's mean; first bounce " << share << " of Cycles'\n";
  bool ok = Within(scene + ", direct light's mean off the 0-bounce render's",
    std::abs(directMean / MeanOf(direct) - 1.0), 0.02, 0.02);
  return Within(scene + ", first bounce short of Cycles'", 1.0 - share, 0.05,
           1.0 - FirstBounceBounds().at(scene)) &&
      ok
    ? EXIT_SUCCESS
    : EXIT_FAILURE;
}

// The share of the emitters' light the pass's own gather gives, asserted today per scene lit
// by emitters alone (goal within 5 %).
const std::map<std::string, double>& EmitterGatherBounds()
{
  static const std::map<std::string, double> bounds = {
    { "emitterroom", 0.25 }, // measured 1.21
  };
  return bounds;
}

// In a scene lit by emitters alone, Cycles counts their light on the surfaces as direct: its
// 0-bounce render (SCENE-b0.pfm) is what the pixels' own gather of the emitting voxels
// (`Bounces` 0, no tail) must give, over the pixels off the emitters (those below a tenth of
// the render's brightest), within 5 % (docs/reference.md, "The small emitter's first gather").
int EmitterGather(const std::string& scene)
{
  voxelgi::metrics::Image direct;
  VOXELGI_CHECK(ReadReference(scene + "-b0", direct), "no 0-bounce reference");
  SceneWindow window(scene, direct.Width, direct.Height);
  VOXELGI_CHECK(window.Added, "no scene " << scene);
  window.View.GI->SetBounces(0);
  window.View.GI->SetBounceTail(false);
  vtkNew<vtkFloatArray> pixels;
  VOXELGI_CHECK(window.Composite(pixels), "GI did not run");
  const voxelgi::metrics::Image image =
    voxelgi::metrics::FromRgba(pixels->GetPointer(0), direct.Width, direct.Height);
  const float brightest = *std::max_element(direct.Rgb.begin(), direct.Rgb.end());
  double pass = 0.0, cycles = 0.0;
  int kept = 0;
  for (std::size_t i = 0; i < direct.Rgb.size(); i += 3)
  {
    const float* c = &direct.Rgb[i];
    if (c[0] + c[1] + c[2] < 0.3f * brightest)
    {
      pass += image.Rgb[i] + image.Rgb[i + 1] + image.Rgb[i + 2];
      cycles += c[0] + c[1] + c[2];
      ++kept;
    }
  }
  const double share = pass / cycles;
  std::cout << scene << ": the pixels' gather of the emitters " << share
            << " of Cycles' 0-bounce render over " << kept << " pixels off the emitters\n";
  return Within(scene + ", emitters' light gathered off Cycles'", std::abs(share - 1.0), 0.05,
           EmitterGatherBounds().at(scene))
    ? EXIT_SUCCESS
    : EXIT_FAILURE;
}
}

int TestGIReference(int argc, char* argv[])
{
  // The test driver passes the test name first; the scene follows (default: the Cornell box).
  std::string scene = "cornell";
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const std::size_t orders = arg.rfind("-orders");
    if (orders != std::string::npos && FirstBounceBounds().count(arg.substr(0, orders)))
    {
      return Orders(arg.substr(0, orders));
    }
    const std::size_t emitters = arg.rfind("-emitters");
    if (emitters != std::string::npos && EmitterGatherBounds().count(arg.substr(0, emitters)))
    {
      return EmitterGather(arg.substr(0, emitters));
    }
    if (SceneBounds().count(arg))
    {
      scene = arg;
    }
  }
  const Bounds& bounds = SceneBounds().at(scene);
  voxelgi::metrics::Image reference;
  VOXELGI_CHECK(ReadReference(scene, reference), "no reference");
  const int w = reference.Width, h = reference.Height;
  const double referenceMean = MeanOf(reference);
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
  // VTK draws volumes and translucent actors over the composite: then the window's image is
  // what the reference shows.
  const bool over = vtkVoxelGIScenes::DrawsOverComposite(renderer);
  auto image = [&](vtkFloatArray* pixels) {
    if (over)
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
         0.6, bounds.FlipRatio) &&
    ok;
  ok = Within(scene + ", error of the mean radiance", std::abs(withGI.Mean / referenceMean - 1.0),
         0.1, bounds.Mean) &&
    ok;
  ok = Within(scene + ", RMSE relative to plain VTK's", withGI.Errors.Rmse / plain.Errors.Rmse,
         0.5, bounds.RmseRatio) &&
    ok;

  if (scene.rfind("contacts", 0) == 0)
  {
    // Under the headlight the seam glows (measured 0.065 above the wall): its voxels hold
    // the floor's and the wall's light in one value. (The contact ring, 1.47 against the
    // reference's 1.39 while voxels sent their light every way, is now 1.38.)
    const bool headlight = scene == "contactsheadlight";
    ok = ContactsHold(scene, renderer,
           voxelgi::metrics::FromRgba(giPixels->GetPointer(0), w, h), reference,
           headlight ? 0.07 : 0.0) &&
      ok;
  }

  if (scene == "volumeroom")
  {
    ok = VolumeLitByRoom(view, renderer,
           voxelgi::metrics::FromRgba(giPixels->GetPointer(0), w, h), reference) &&
      ok;
  }

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
