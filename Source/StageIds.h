/**
 * The stages' ids and names, for the stage clock (which stages ran, their times). The public
 * `vtkVoxelGIPass::Stages` enum gives the same values to users (the pass checks that the two
 * agree at compile time), so that stages need not include the public class.
 */
#ifndef VoxelGIStageIds_h
#define VoxelGIStageIds_h

namespace voxelgi
{
namespace stage
{
enum Id
{
  Scan = 0,
  Clear,
  VoxelizeStatic,
  VoxelizeDynamic,
  Volumes,
  Resolve,
  ShadowMaps,
  LightVoxels,
  Mipmap,
  Bounce,
  GBuffer,
  ConeTrace,
  Composite,
  Present,
  DebugView,
  Count
};

/// The stage's name ("Unknown" out of range).
const char* Name(int id);
}
}

#endif
