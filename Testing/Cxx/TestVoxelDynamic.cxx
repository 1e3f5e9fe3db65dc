// Static/dynamic split: a dynamic actor that moves is revoxelized alone (clear-dynamic +
// dynamic voxelization), static voxels stay flagged and untouched; an unchanged frame does
// no voxel work (the last traced image is presented again); a static actor that moves triggers
// a full revoxelization and, with AutoDynamic, becomes dynamic. The clear and the bounce
// run over the bricks the resolve found occupied: places left behind are empty and dark.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"

#include "vtkActor.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cstdlib>
#include <string>

namespace
{
using voxelgi_test::StagesRan;

// Value (first component) of a volume at the voxel containing world point p.
double At(vtkVoxelGIPass* gi, vtkImageData* image, double x, double y, double z)
{
  double origin[3];
  gi->GetGridOrigin(origin);
  const double h = gi->GetGridVoxelSize();
  const int n = gi->GetGridResolution();
  const int i = static_cast<int>((x - origin[0]) / h), j = static_cast<int>((y - origin[1]) / h),
            k = static_cast<int>((z - origin[2]) / h);
  return image->GetPointData()->GetScalars()->GetComponent(i + n * (j + n * k), 0);
}
}

namespace
{
const std::string Relight = ",LightVoxels,Mipmap,Bounce,GBuffer,ConeTrace,Composite,Present";
const std::string Unchanged = "Scan,Present";
}

int TestVoxelDynamic(int, char*[])
{
  vtkNew<vtkPlaneSource> floorSource;
  floorSource->SetOrigin(0, 0, 0);
  floorSource->SetPoint1(4, 0, 0);
  floorSource->SetPoint2(0, 4, 0);
  vtkNew<vtkPolyDataMapper> floorMapper;
  floorMapper->SetInputConnection(floorSource->GetOutputPort());
  vtkNew<vtkActor> floor;
  floor->SetMapper(floorMapper);

  vtkNew<vtkCubeSource> cubeSource;
  cubeSource->SetBounds(0.5, 1.0, 0.5, 1.0, 0.5, 1.0);
  vtkNew<vtkPolyDataMapper> cubeMapper;
  cubeMapper->SetInputConnection(cubeSource->GetOutputPort());
  vtkNew<vtkActor> cube;
  cube->SetMapper(cubeMapper);
  vtkVoxelGIPass::SetPropDynamic(cube, true);

  vtkNew<vtkCubeSource> postSource;
  postSource->SetBounds(3.0, 3.5, 3.0, 3.5, 0.0, 2.0);
  vtkNew<vtkPolyDataMapper> postMapper;
  postMapper->SetInputConnection(postSource->GetOutputPort());
  vtkNew<vtkActor> post;
  post->SetMapper(postMapper);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(floor);
  renderer->AddActor(cube);
  renderer->AddActor(post);
  voxelgi_test::GIWindow view(renderer, 32, 64);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  renderer->ResetCamera();

  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
  VOXELGI_CHECK(StagesRan(gi) == "Scan,Clear,VoxelizeStatic,VoxelizeDynamic,Resolve" + Relight,
    "first frame ran " << StagesRan(gi));

  window->Render();
  VOXELGI_CHECK(StagesRan(gi) == Unchanged, "unchanged frame ran " << StagesRan(gi));

  // Move the dynamic cube 2 units along +x (grid covers the floor, so no refit).
  cube->SetPosition(2.0, 0.0, 0.0);
  window->Render();
  VOXELGI_CHECK(StagesRan(gi) == "Scan,Clear,VoxelizeDynamic,Resolve" + Relight,
    "dynamic move ran " << StagesRan(gi));

  vtkNew<vtkImageData> counts;
  vtkNew<vtkImageData> flags;
  VOXELGI_CHECK(gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_COUNT, counts), "no counts");
  VOXELGI_CHECK(gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_FLAG, flags), "no flags");
  // cube top face: old place empty, new place occupied and not flagged static
  VOXELGI_CHECK(At(gi, counts, 0.75, 0.75, 1.0) == 0, "old cube position still voxelized");
  VOXELGI_CHECK(At(gi, counts, 2.75, 0.75, 1.0) > 0, "new cube position not voxelized");
  VOXELGI_CHECK(At(gi, flags, 2.75, 0.75, 1.0) == 0, "dynamic voxel flagged static");
  // floor and post are static and survived the clear
  VOXELGI_CHECK(At(gi, counts, 2.0, 2.0, 0.0) > 0, "static floor voxel lost");
  VOXELGI_CHECK(At(gi, flags, 2.0, 2.0, 0.0) == 1, "static floor voxel not flagged");
  VOXELGI_CHECK(At(gi, counts, 3.25, 3.25, 2.0) > 0, "static post voxel lost");
  // The bounce runs over the bricks found occupied: the emptied place stays dark.
  vtkNew<vtkImageData> radiance;
  VOXELGI_CHECK(gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_RADIANCE, radiance), "no radiance");
  VOXELGI_CHECK(At(gi, radiance, 0.75, 0.75, 1.0) == 0.0, "old cube position still lit");
  VOXELGI_CHECK(At(gi, radiance, 2.75, 0.75, 1.0) > 0.0, "new cube position not lit");

  // A static actor moves: full revoxelization; AutoDynamic makes it dynamic from now on.
  post->SetPosition(-2.0, 0.0, 0.0);
  window->Render();
  VOXELGI_CHECK(StagesRan(gi) == "Scan,Clear,VoxelizeStatic,VoxelizeDynamic,Resolve" + Relight,
    "static move ran " << StagesRan(gi));
  VOXELGI_CHECK(gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_COUNT, counts), "no counts");
  VOXELGI_CHECK(At(gi, counts, 3.25, 3.25, 2.0) == 0, "old post position still voxelized");
  VOXELGI_CHECK(At(gi, counts, 1.25, 3.25, 2.0) > 0, "moved post not voxelized");
  VOXELGI_CHECK(gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_RADIANCE, radiance), "no radiance");
  VOXELGI_CHECK(At(gi, radiance, 3.25, 3.25, 2.0) == 0.0, "old post position still lit");
  post->SetPosition(-2.0, -1.0, 0.0);
  window->Render();
  VOXELGI_CHECK(StagesRan(gi) == "Scan,Clear,VoxelizeDynamic,Resolve" + Relight,
    "second move of the auto-dynamic post ran " << StagesRan(gi));
  return EXIT_SUCCESS;
}
