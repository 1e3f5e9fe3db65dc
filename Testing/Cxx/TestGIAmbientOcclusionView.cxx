// AO-only view of the Cornell box: corners, the floor under and beside the blocks darker.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"

int TestGIAmbientOcclusionView(int argc, char* argv[])
{
  return voxelgi_test::CornellRegressionTest(
    argc, argv, vtkVoxelGIPass::DEBUG_VIEW_AMBIENT_OCCLUSION);
}
