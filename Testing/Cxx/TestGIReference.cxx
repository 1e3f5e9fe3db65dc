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
#include <string>

namespace
{
voxelgi::metrics::Errors Score(vtkFloatArray* rgba, const voxelgi::metrics::Image& reference,
  const char* label)
{
  const voxelgi::metrics::Errors e = voxelgi::metrics::Compare(
    voxelgi::metrics::FromRgba(rgba->GetPointer(0), reference.Width, reference.Height), reference);
  std::cout << label << ": RMSE " << e.Rmse << ", relMSE " << e.RelMse << ", SSIM " << e.Ssim
            << ", FLIP " << e.Flip << "\n";
  return e;
}
}

int TestGIReference(int, char*[])
{
  voxelgi::metrics::Image reference;
  const std::string path = std::string(VOXELGI_TEST_DATA_DIR) + "/Reference/cornell.pfm";
  VOXELGI_CHECK(voxelgi::metrics::ReadPfm(path, reference), "cannot read " << path);
  const int w = reference.Width, h = reference.Height;

  vtkNew<vtkRenderer> renderer;
  vtkVoxelGIScenes::AddCornellBox(renderer);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(w, h);
  window->AddRenderer(renderer);
  window->Render();
  vtkNew<vtkFloatArray> plainPixels;
  window->GetRGBAPixelData(0, 0, w - 1, h - 1, 0, plainPixels);
  const voxelgi::metrics::Errors plain = Score(plainPixels, reference, "plain VTK");

  vtkNew<vtkVoxelGIPass> gi;
  renderer->SetPass(gi);
  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
  VOXELGI_CHECK(voxelgi_test::AllFinite(gi), "non-finite values");
  vtkNew<vtkFloatArray> giPixels;
  VOXELGI_CHECK(gi->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, giPixels), "no image");
  const voxelgi::metrics::Errors withGI = Score(giPixels, reference, "voxel GI (defaults)");

  VOXELGI_CHECK(withGI.Rmse < plain.Rmse, "GI is not closer to the reference (RMSE)");
  VOXELGI_CHECK(withGI.RelMse < plain.RelMse, "GI is not closer to the reference (relMSE)");
  VOXELGI_CHECK(withGI.Ssim > plain.Ssim, "GI is not closer to the reference (SSIM)");
  VOXELGI_CHECK(withGI.Flip < plain.Flip, "GI is not closer to the reference (FLIP)");
  return EXIT_SUCCESS;
}
