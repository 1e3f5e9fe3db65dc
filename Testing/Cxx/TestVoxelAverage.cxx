// More than 255 fragments in one voxel: the voxel's albedo must be the exact mean of the
// fragments' (8-bit) colours and the count exact, where a packed RGBA8 running average with
// an 8-bit counter would overflow.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <cstdlib>

int TestVoxelAverage(int, char*[])
{
  const int res = 16;
  const int fragments = 600;
  // Anchors pin the bounds to [0, 1]^3: grid origin -0.05, voxel 1.1 / 16, so voxel
  // (8, 8, 8) spans [0.5, 0.56875] on each axis.
  const double lo = 0.51, hi = 0.555, tiny = 0.004;

  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  auto uniform = [&random](double a, double b) {
    random->Next();
    return random->GetRangeValue(a, b);
  };

  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(3);
  double sum[3] = { 0, 0, 0 };
  auto addTriangle = [&](double x, double y, double z, const unsigned char rgb[3]) {
    vtkIdType ids[3] = { points->InsertNextPoint(x, y, z),
      points->InsertNextPoint(x + tiny, y, z + 0.3 * tiny),
      points->InsertNextPoint(x, y + tiny, z + 0.6 * tiny) };
    cells->InsertNextCell(3, ids);
    for (int k = 0; k < 3; ++k)
    {
      colors->InsertNextTypedTuple(rgb);
    }
  };
  const unsigned char grey[3] = { 128, 128, 128 };
  addTriangle(0.0, 0.0, 0.0, grey);
  addTriangle(1.0 - tiny, 1.0 - tiny, 1.0, grey);
  for (int i = 0; i < fragments; ++i)
  {
    const unsigned char rgb[3] = { static_cast<unsigned char>(uniform(0, 255.99)),
      static_cast<unsigned char>(uniform(0, 255.99)), static_cast<unsigned char>(uniform(0, 255.99)) };
    for (int c = 0; c < 3; ++c)
    {
      sum[c] += rgb[c];
    }
    addTriangle(uniform(lo, hi - tiny), uniform(lo, hi - tiny), uniform(lo, hi - tiny), rgb);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(cells);
  poly->GetPointData()->SetScalars(colors);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->SetColorModeToDirectScalars();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  voxelgi_test::GIWindow view(renderer, res, 64);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  gi->SetGridPadding(0.05);
  renderer->ResetCamera();
  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");

  vtkNew<vtkImageData> counts;
  vtkNew<vtkImageData> albedo;
  VOXELGI_CHECK(gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_COUNT, counts), "no counts");
  VOXELGI_CHECK(gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, albedo), "no albedo");
  const vtkIdType voxel = 8 + res * (8 + res * 8);
  const double count = counts->GetPointData()->GetScalars()->GetTuple1(voxel);
  const double* rgba = albedo->GetPointData()->GetScalars()->GetTuple4(voxel);
  std::cout << "count " << count << " (expected " << fragments << "), albedo " << rgba[0] << " "
            << rgba[1] << " " << rgba[2] << " (expected " << sum[0] / fragments << " "
            << sum[1] / fragments << " " << sum[2] / fragments << ")" << std::endl;
  VOXELGI_CHECK(count == fragments, "count " << count);
  for (int c = 0; c < 3; ++c)
  {
    // The stored RGBA8 rounds the exact mean once.
    VOXELGI_CHECK(std::abs(rgba[c] - sum[c] / fragments) <= 0.51, "channel " << c);
  }
  VOXELGI_CHECK(rgba[3] == 255, "voxel not marked occupied");
  return EXIT_SUCCESS;
}
