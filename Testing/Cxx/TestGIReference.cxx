// Error against the path-traced reference: the Cornell box rendered by Blender Cycles
// (Testing/Reference, Testing/Data/Reference/cornell.pfm). With its default settings the pass
// must come closer to the reference than plain VTK shading in all four metrics (RMSE,
// relMSE, SSIM, FLIP), which are printed for both.
#include "ImageMetrics.h"
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cstdlib>
#include <fstream>
#include <string>

namespace
{
// Portable float map, as render_cycles.py writes it: "PF", width height, -1 (little endian),
// rows bottom to top.
bool ReadPfm(const std::string& path, voxelgi::metrics::Image& image)
{
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  double scale = 0.0;
  in >> magic >> image.Width >> image.Height >> scale;
  in.get(); // the single whitespace before the data
  if (!in || magic != "PF" || scale >= 0.0 || image.Width <= 0 || image.Height <= 0)
  {
    return false;
  }
  image.Rgb.resize(static_cast<std::size_t>(image.Width) * image.Height * 3);
  in.read(reinterpret_cast<char*>(image.Rgb.data()),
    static_cast<std::streamsize>(image.Rgb.size() * sizeof(float)));
  return static_cast<bool>(in);
}

voxelgi::metrics::Image FromRgba(vtkFloatArray* rgba, int w, int h)
{
  voxelgi::metrics::Image image;
  image.Width = w;
  image.Height = h;
  for (vtkIdType i = 0; i < rgba->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      image.Rgb.push_back(rgba->GetComponent(i, c));
    }
  }
  return image;
}

struct Scores
{
  double Rmse, RelMse, Ssim, Flip;
};

Scores Score(const voxelgi::metrics::Image& test, const voxelgi::metrics::Image& reference,
  const char* label)
{
  const Scores s = { voxelgi::metrics::Rmse(test, reference),
    voxelgi::metrics::RelMse(test, reference), voxelgi::metrics::Ssim(test, reference),
    voxelgi::metrics::Flip(test, reference) };
  std::cout << label << ": RMSE " << s.Rmse << ", relMSE " << s.RelMse << ", SSIM " << s.Ssim
            << ", FLIP " << s.Flip << "\n";
  return s;
}
}

int TestGIReference(int, char*[])
{
  voxelgi::metrics::Image reference;
  const std::string path = std::string(VOXELGI_TEST_DATA_DIR) + "/Reference/cornell.pfm";
  VOXELGI_CHECK(ReadPfm(path, reference), "cannot read " << path);
  const int w = reference.Width, h = reference.Height;

  vtkNew<vtkRenderer> renderer;
  vtkVoxelGIScenes::AddCornellBox(renderer);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(w, h);
  window->AddRenderer(renderer);
  window->Render();
  vtkNew<vtkFloatArray> plainPixels;
  window->GetRGBAPixelData(0, 0, w - 1, h - 1, 0, plainPixels);
  const Scores plain = Score(FromRgba(plainPixels, w, h), reference, "plain VTK");

  vtkNew<vtkVoxelGIPass> gi;
  renderer->SetPass(gi);
  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
  VOXELGI_CHECK(voxelgi_test::AllFinite(gi), "non-finite values");
  vtkNew<vtkFloatArray> giPixels;
  VOXELGI_CHECK(gi->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, giPixels), "no image");
  const Scores withGI = Score(FromRgba(giPixels, w, h), reference, "voxel GI (defaults)");

  VOXELGI_CHECK(withGI.Rmse < plain.Rmse, "GI is not closer to the reference (RMSE)");
  VOXELGI_CHECK(withGI.RelMse < plain.RelMse, "GI is not closer to the reference (relMSE)");
  VOXELGI_CHECK(withGI.Ssim > plain.Ssim, "GI is not closer to the reference (SSIM)");
  VOXELGI_CHECK(withGI.Flip < plain.Flip, "GI is not closer to the reference (FLIP)");
  return EXIT_SUCCESS;
}
