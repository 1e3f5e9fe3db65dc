// Image slices are voxelized as the textured quads VTK draws them as, in the colours VTK
// shows. A 20^3 image (spacing 0.1) whose value is 10 x its i index: an image actor's z slice
// (k = 10) in grey by window 200 and level 100, and a vtkImageSliceMapper's x slice (i = 5,
// value 50) through a lookup table over its own range. The voxel on each slice holds that
// colour; a translucent image actor's y slice and a vtkImageResliceMapper slice are left out
// (their voxels stay empty) and named in the notice.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"

#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageProperty.h"
#include "vtkImageResliceMapper.h"
#include "vtkImageSlice.h"
#include "vtkImageSliceMapper.h"
#include "vtkLight.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <cstdlib>
#include <string>

int TestVoxelImageSlices(int, char*[])
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(20, 20, 20);
  image->SetSpacing(0.1, 0.1, 0.1);
  image->AllocateScalars(VTK_UNSIGNED_SHORT, 1);
  for (int k = 0; k < 20; ++k)
  {
    for (int j = 0; j < 20; ++j)
    {
      for (int i = 0; i < 20; ++i)
      {
        image->SetScalarComponentFromDouble(i, j, k, 0, 10.0 * i);
      }
    }
  }
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkImageActor> axial;
  axial->GetMapper()->SetInputData(image);
  axial->SetDisplayExtent(0, 19, 0, 19, 10, 10);
  axial->GetProperty()->SetColorWindow(200.0);
  axial->GetProperty()->SetColorLevel(100.0);
  renderer->AddViewProp(axial);
  vtkNew<vtkLookupTable> lut;
  lut->SetRange(0.0, 190.0);
  lut->SetHueRange(0.0, 0.66);
  lut->Build();
  vtkNew<vtkImageSliceMapper> sagittalMapper;
  sagittalMapper->SetInputData(image);
  sagittalMapper->SetOrientationToX();
  sagittalMapper->SetSliceNumber(5);
  vtkNew<vtkImageSlice> sagittal;
  sagittal->SetMapper(sagittalMapper);
  sagittal->GetProperty()->SetLookupTable(lut);
  sagittal->GetProperty()->UseLookupTableScalarRangeOn();
  renderer->AddViewProp(sagittal);
  vtkNew<vtkImageActor> coronal; // translucent: left to VTK
  coronal->GetMapper()->SetInputData(image);
  coronal->SetDisplayExtent(0, 19, 12, 12, 0, 19);
  coronal->GetProperty()->SetOpacity(0.5);
  renderer->AddViewProp(coronal);
  vtkNew<vtkImageResliceMapper> resliceMapper;
  resliceMapper->SetInputData(image);
  vtkNew<vtkImageSlice> oblique; // drawn by a reslice mapper: left to VTK
  oblique->SetMapper(resliceMapper);
  renderer->AddViewProp(oblique);

  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(3.0, 3.0, 5.0);
  light->SetFocalPoint(1.0, 1.0, 1.0);
  renderer->AddLight(light);
  voxelgi_test::GIWindow view(renderer, 64, 64);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  voxelgi_test::Messages warnings(gi);
  renderer->ResetCamera();
  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
  std::cout << "notice: " << warnings.Text << std::endl;
  VOXELGI_CHECK(warnings.Text.find("vtkImageActor (translucent)") != std::string::npos,
    "the translucent slice is not named");
  VOXELGI_CHECK(warnings.Text.find("vtkImageSlice with a vtkImageResliceMapper") != std::string::npos,
    "the reslice mapper's slice is not named");

  vtkNew<vtkImageData> albedo;
  VOXELGI_CHECK(gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, albedo), "no albedo");
  auto voxel = [&](double x, double y, double z) {
    double p[3] = { x, y, z };
    return albedo->GetPointData()->GetScalars()->GetTuple4(albedo->FindPoint(p));
  };
  // The z slice at x = 1.5: value 150, grey (150 - 0) / 200.
  const double* grey = voxel(1.5, 0.5, 1.0);
  std::cout << "z slice: " << grey[0] << " " << grey[1] << " " << grey[2] << " " << grey[3] << std::endl;
  VOXELGI_CHECK(grey[3] == 255, "the image actor's slice is not voxelized");
  for (int c = 0; c < 3; ++c)
  {
    VOXELGI_CHECK(std::abs(grey[c] - 0.75 * 255.0) <= 8.0, "grey channel " << c);
  }
  // The x slice: value 50 through the table.
  double expected[3];
  lut->GetColor(50.0, expected);
  const double* coloured = voxel(0.5, 1.5, 0.3);
  std::cout << "x slice: " << coloured[0] << " " << coloured[1] << " " << coloured[2] << " "
            << coloured[3] << ", table " << 255.0 * expected[0] << " " << 255.0 * expected[1]
            << " " << 255.0 * expected[2] << std::endl;
  VOXELGI_CHECK(coloured[3] == 255, "the slice mapper's slice is not voxelized");
  for (int c = 0; c < 3; ++c)
  {
    VOXELGI_CHECK(std::abs(coloured[c] - 255.0 * expected[c]) <= 8.0, "table channel " << c);
  }
  VOXELGI_CHECK(voxel(1.2, 1.2, 0.4)[3] == 0, "the translucent slice is voxelized");
  return EXIT_SUCCESS;
}
