// Large images are traced at half their resolution (MaxTraceMegapixels). In a window of 1.1
// megapixels the pass at its defaults must give exactly the image of a pass told to trace at
// half the resolution with no limit, an image close to but not the same as a full trace; in
// a window of exactly one megapixel it must trace every pixel (the same image as with no
// limit).
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkFloatArray.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cstdlib>
#include <iostream>

namespace
{
// The composite after rendering with `resolution` and `limit`.
vtkSmartPointer<vtkFloatArray> Render(voxelgi_test::GIWindow& view, double resolution, double limit)
{
  view.GI->SetTraceResolution(resolution);
  view.GI->SetMaxTraceMegapixels(limit);
  view.Window->Render();
  return view.GI->GetGIActive() && voxelgi_test::AllFinite(view.GI)
    ? voxelgi_test::Composite(view.GI)
    : nullptr;
}
}

int TestGITraceScale(int, char*[])
{
  voxelgi_test::GIWindow view(nullptr, 32, 200, 0);
  vtkVoxelGIScenes::AddCornellBox(view.Renderer);
  view.GI->SetDiffuseConeCount(4);
  VOXELGI_CHECK(view.GI->GetMaxTraceMegapixels() == 1.0, "the limit's default is not 1");

  view.Window->SetSize(1100, 1000);
  vtkSmartPointer<vtkFloatArray> limited = Render(view, 1.0, 1.0);
  vtkSmartPointer<vtkFloatArray> half = Render(view, 0.5, 0.0);
  vtkSmartPointer<vtkFloatArray> full = Render(view, 1.0, 0.0);
  VOXELGI_CHECK(limited && half && full, "GI did not run or left non-finite values");
  const double halfDifference = voxelgi_test::MaxDifference(limited, half);
  const double fullDifference = voxelgi_test::MaxDifference(limited, full);
  const voxelgi_test::ImageDifference fromFull = voxelgi_test::Differences(limited, full, 0.1);
  const double fullMean = fromFull.Mean;
  const double over = fromFull.Over;
  std::cout << "1100 x 1000: largest difference to half the resolution " << halfDifference
            << ", to every pixel traced " << fullDifference << " (mean " << fullMean << ", "
            << 100.0 * over << " % of the pixels over 0.1)" << std::endl;
  VOXELGI_CHECK(halfDifference == 0.0, "not traced at half the resolution: " << halfDifference);
  VOXELGI_CHECK(fullDifference > 1e-3, "traced at the full resolution");
  // Measured (llvmpipe): mean 0.0016; 0.32 % of the pixels differ by more than 0.1 (the
  // largest 0.52).
  VOXELGI_CHECK(fullMean < 0.003, "half the resolution moved the image: mean " << fullMean);
  VOXELGI_CHECK(over < 0.01, "half the resolution moved " << 100.0 * over << " % of the pixels");

  view.Window->SetSize(1000, 1000);
  limited = Render(view, 1.0, 1.0);
  full = Render(view, 1.0, 0.0);
  VOXELGI_CHECK(limited && full, "GI did not run or left non-finite values");
  const double atLimit = voxelgi_test::MaxDifference(limited, full);
  std::cout << "1000 x 1000: largest difference to every pixel traced " << atLimit << std::endl;
  VOXELGI_CHECK(atLimit == 0.0, "one megapixel was not traced in full: " << atLimit);
  return EXIT_SUCCESS;
}
