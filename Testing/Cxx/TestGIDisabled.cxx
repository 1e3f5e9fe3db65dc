// With GI disabled the pass must render exactly what VTK renders without it: the Cornell box
// rendered with a disabled vtkVoxelGIPass and with no pass at all are compared pixel by
// pixel; the image is also compared with its baseline.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <cstdlib>

int TestGIDisabled(int argc, char* argv[])
{
  vtkNew<vtkRenderer> plainRenderer;
  vtkVoxelGIScenes::AddCornellBox(plainRenderer);
  vtkNew<vtkRenderWindow> plainWindow;
  plainWindow->SetSize(300, 300);
  plainWindow->AddRenderer(plainRenderer);
  plainWindow->Render();
  vtkNew<vtkUnsignedCharArray> plain;
  plainWindow->GetRGBACharPixelData(0, 0, 299, 299, 0, plain);

  vtkNew<vtkRenderer> renderer;
  vtkVoxelGIScenes::AddCornellBox(renderer);
  voxelgi_test::GIWindow view(renderer, 0, 300); // the pass's default voxels
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  gi->EnabledOff();
  window->Render();
  VOXELGI_CHECK(!gi->GetGIActive(), "GI ran although disabled");
  VOXELGI_CHECK(gi->GetVoxelMemoryBytes() == 0, "disabled GI allocated voxel memory");
  vtkNew<vtkUnsignedCharArray> passed;
  window->GetRGBACharPixelData(0, 0, 299, 299, 0, passed);

  vtkIdType differing = 0;
  for (vtkIdType i = 0; i < plain->GetNumberOfValues(); ++i)
  {
    differing += plain->GetValue(i) != passed->GetValue(i);
  }
  std::cout << differing << " of " << plain->GetNumberOfValues() << " bytes differ" << std::endl;
  VOXELGI_CHECK(differing == 0, "GI-disabled image differs from plain VTK");
  return voxelgi_test::ImageMatches(argc, argv, window);
}
