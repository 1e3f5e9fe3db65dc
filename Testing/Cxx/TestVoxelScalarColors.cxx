// Scalar colouring through a lookup table voxelizes with the colours VTK shows: a sphere
// coloured by elevation; each voxel's albedo must match the lookup table's colour for the
// elevation at the voxel centre. Also compared as an image of the voxel albedo view.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkElevationFilter.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cstdlib>

int TestVoxelScalarColors(int argc, char* argv[])
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(sphere->GetOutputPort());
  elevation->SetLowPoint(0, -1, 0);
  elevation->SetHighPoint(0, 1, 0);
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->SetNumberOfTableValues(256);
  lut->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(elevation->GetOutputPort());
  mapper->SetLookupTable(lut);
  mapper->SetScalarRange(0.0, 1.0);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.1);
  voxelgi_test::GIWindow view(renderer, 32, 300);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  gi->SetDebugViewToVoxelAlbedo();
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Elevation(20);
  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");

  vtkNew<vtkImageData> albedo;
  VOXELGI_CHECK(gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, albedo), "no albedo");
  vtkDataArray* voxels = albedo->GetPointData()->GetScalars();
  double error = 0.0;
  int occupied = 0;
  for (vtkIdType i = 0; i < voxels->GetNumberOfTuples(); ++i)
  {
    const double* rgba = voxels->GetTuple4(i);
    if (rgba[3] == 0)
    {
      continue;
    }
    double p[3];
    albedo->GetPoint(i, p);
    const double s = std::min(std::max(0.5 * (p[1] + 1.0), 0.0), 1.0);
    double expected[3];
    lut->GetColor(s, expected);
    for (int c = 0; c < 3; ++c)
    {
      error += std::abs(rgba[c] / 255.0 - expected[c]);
    }
    ++occupied;
  }
  const double meanError = error / (3.0 * occupied);
  std::cout << occupied << " voxels, mean |albedo - LUT colour| = " << meanError << std::endl;
  VOXELGI_CHECK(occupied > 500, "too few voxels");
  // A voxel averages the colours over its extent (1/16 of the scalar range here).
  VOXELGI_CHECK(meanError < 0.05, "voxel colours differ from the lookup table");

  return voxelgi_test::ImageMatches(argc, argv, window);
}
