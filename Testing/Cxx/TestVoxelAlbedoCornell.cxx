// Voxel albedo debug view of the Cornell box: the walls' red/green/white, the blocks and the
// ceiling panel must appear as voxels where VTK draws them.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

int TestVoxelAlbedoCornell(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  vtkVoxelGIScenes::AddCornellBox(renderer);
  voxelgi_test::GIWindow view(renderer, 64, 300);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  gi->SetDebugViewToVoxelAlbedo();
  window->Render();
  if (!gi->GetGIActive())
  {
    std::cerr << "GI did not run on the Cornell box." << std::endl;
    return EXIT_FAILURE;
  }

  return voxelgi_test::ImageMatches(argc, argv, window);
}
