// Indirect-only view of the Cornell box: the indirect diffuse (and specular) light alone,
// red and green bleeding onto the white surfaces.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"

int TestGIIndirectView(int argc, char* argv[])
{
  return voxelgi_test::CornellRegressionTest(argc, argv, vtkVoxelGIPass::DEBUG_VIEW_INDIRECT);
}
