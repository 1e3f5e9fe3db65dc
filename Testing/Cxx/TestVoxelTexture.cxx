// A textured actor voxelizes with its texture's colours: a plane carrying a 2x2 texture
// (red, green, blue, yellow quadrants, nearest filtering). Each quadrant's voxels must have
// its colour; also compared as an image of the voxel albedo view.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"

#include <cstdlib>

int TestVoxelTexture(int argc, char* argv[])
{
  const unsigned char quadrants[4][3] = { { 220, 30, 30 }, { 30, 200, 30 }, { 30, 30, 220 },
    { 230, 220, 40 } };
  vtkNew<vtkImageData> image;
  image->SetDimensions(2, 2, 1);
  vtkNew<vtkUnsignedCharArray> texels;
  texels->SetNumberOfComponents(3);
  for (const auto& rgb : quadrants)
  {
    texels->InsertNextTypedTuple(rgb);
  }
  image->GetPointData()->SetScalars(texels);
  vtkNew<vtkTexture> texture;
  texture->SetInputData(image);
  texture->InterpolateOff();

  // Plane in z = 0 spanning [0, 2] x [0, 2]; texture coordinates run 0..1 across it.
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0, 0, 0);
  plane->SetPoint1(2, 0, 0);
  plane->SetPoint2(0, 2, 0);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(texture);
  actor->RotateX(-30); // not axis-aligned: exercises the dominant-axis projection

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.1);
  voxelgi_test::GIWindow view(renderer, 32, 300);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  gi->SetDebugViewToVoxelAlbedo();
  renderer->ResetCamera();
  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");

  vtkNew<vtkImageData> albedo;
  VOXELGI_CHECK(gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, albedo), "no albedo");
  vtkDataArray* voxels = albedo->GetPointData()->GetScalars();
  // Check the voxel at the centre of each quadrant (plane coordinates u, v in [0, 2]).
  const double centers[4][2] = { { 0.5, 0.5 }, { 1.5, 0.5 }, { 0.5, 1.5 }, { 1.5, 1.5 } };
  for (int q = 0; q < 4; ++q)
  {
    double world[4] = { centers[q][0], centers[q][1], 0.0, 1.0 };
    actor->GetMatrix()->MultiplyPoint(world, world);
    const vtkIdType id = albedo->FindPoint(world);
    const double* rgba = voxels->GetTuple4(id);
    std::cout << "quadrant " << q << ": " << rgba[0] << " " << rgba[1] << " " << rgba[2]
              << std::endl;
    VOXELGI_CHECK(rgba[3] == 255, "quadrant " << q << " not voxelized");
    for (int c = 0; c < 3; ++c)
    {
      VOXELGI_CHECK(std::abs(rgba[c] - quadrants[q][c]) <= 2, "quadrant " << q << " channel " << c);
    }
  }
  return voxelgi_test::ImageMatches(argc, argv, window);
}
