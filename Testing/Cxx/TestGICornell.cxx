// Full GI on the Cornell box: colour bleeding must be visible on the white walls, red near
// the red wall and green near the green wall (measured on the indirect float image), and the
// composite is compared with its baseline.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cstdlib>

int TestGICornell(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  vtkVoxelGIScenes::AddCornellBox(renderer);
  voxelgi_test::GIWindow view(renderer);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
  VOXELGI_CHECK(voxelgi_test::AllFinite(gi), "non-finite values");

  vtkNew<vtkFloatArray> indirect;
  VOXELGI_CHECK(gi->GetFloatImage(vtkVoxelGIPass::IMAGE_INDIRECT, indirect), "no indirect image");
  // The back wall spans about x in [36, 164], y in [36, 164] of the 200 x 200 image; compare
  // strips next to the red (left) and green (right) walls, above the blocks.
  const double leftRed = voxelgi_test::MeanOver(indirect, 200, 40, 120, 55, 160, 0);
  const double leftGreen = voxelgi_test::MeanOver(indirect, 200, 40, 120, 55, 160, 1);
  const double rightRed = voxelgi_test::MeanOver(indirect, 200, 145, 120, 160, 160, 0);
  const double rightGreen = voxelgi_test::MeanOver(indirect, 200, 145, 120, 160, 160, 1);
  std::cout << "indirect on the back wall: left (r, g) = (" << leftRed << ", " << leftGreen
            << "), right (r, g) = (" << rightRed << ", " << rightGreen << ")" << std::endl;
  VOXELGI_CHECK(leftRed > 1.2 * leftGreen, "no red bleeding next to the red wall");
  VOXELGI_CHECK(rightGreen > 1.2 * rightRed, "no green bleeding next to the green wall");
  VOXELGI_CHECK(leftRed > 0.01 && rightGreen > 0.01, "indirect light too weak to see");

  return voxelgi_test::ImageMatches(argc, argv, window);
}
