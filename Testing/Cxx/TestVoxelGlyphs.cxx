// A vtkGlyph3DMapper's instances are voxelized like polygons: every instance, at its position
// and scale, with its own colour. Three square glyphs (vtkPlaneSource, unit size, facing z)
// at x = 0, 2 and 4, coloured red, green and blue by direct scalars, the third scaled by 2
// through the scale array: the voxel at each centre holds that instance's colour, the voxel
// 0.8 right of the third centre is covered only because of its scale, and the gap between
// the first two stays empty.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"

#include "vtkActor.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <cstdlib>

int TestVoxelGlyphs(int, char*[])
{
  vtkNew<vtkPoints> centres;
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(3);
  colors->SetName("colors");
  vtkNew<vtkDoubleArray> scales;
  scales->SetName("scales");
  const unsigned char rgb[3][3] = { { 255, 0, 0 }, { 0, 255, 0 }, { 0, 0, 255 } };
  for (int i = 0; i < 3; ++i)
  {
    centres->InsertNextPoint(2.0 * i, 0.0, 0.0);
    colors->InsertNextTypedTuple(rgb[i]);
    scales->InsertNextValue(i == 2 ? 2.0 : 1.0);
  }
  vtkNew<vtkPolyData> points;
  points->SetPoints(centres);
  points->GetPointData()->SetScalars(colors);
  points->GetPointData()->AddArray(scales);
  vtkNew<vtkPlaneSource> square;
  vtkNew<vtkGlyph3DMapper> glyphs;
  glyphs->SetInputData(points);
  glyphs->SetSourceConnection(square->GetOutputPort());
  glyphs->SetScaleArray("scales");
  glyphs->SetScaleModeToScaleByMagnitude();
  glyphs->SetColorModeToDirectScalars();
  vtkNew<vtkActor> actor;
  actor->SetMapper(glyphs);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(2.0, 0.0, 5.0);
  light->SetFocalPoint(2.0, 0.0, 0.0);
  renderer->AddLight(light);
  voxelgi_test::GIWindow view(renderer, 32, 64);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  renderer->ResetCamera();
  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");

  vtkNew<vtkImageData> albedo;
  VOXELGI_CHECK(gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, albedo), "no albedo");
  auto voxel = [&](double x) {
    double p[3] = { x, 0.0, 0.0 };
    const vtkIdType id = albedo->FindPoint(p);
    return albedo->GetPointData()->GetScalars()->GetTuple4(id);
  };
  for (int i = 0; i < 3; ++i)
  {
    const double* v = voxel(2.0 * i);
    std::cout << "instance " << i << " centre: " << v[0] << " " << v[1] << " " << v[2] << " "
              << v[3] << std::endl;
    VOXELGI_CHECK(v[3] == 255, "instance " << i << " not voxelized");
    for (int c = 0; c < 3; ++c)
    {
      VOXELGI_CHECK(std::abs(v[c] - rgb[i][c]) <= 1.0, "instance " << i << " channel " << c);
    }
  }
  const double* scaled = voxel(4.8);
  VOXELGI_CHECK(scaled[3] == 255 && scaled[2] > 250, "the third instance is not scaled");
  VOXELGI_CHECK(voxel(1.0)[3] == 0, "the voxel between the first two instances is occupied");
  return EXIT_SUCCESS;
}
