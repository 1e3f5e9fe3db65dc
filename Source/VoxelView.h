/**
 * A read-only view of the voxels a pass owns: what a pass that shares them
 * (vtkVoxelGIPass::SetVoxelSource) traces and how current they are, and what read-back reads.
 */
#ifndef VoxelGIVoxelView_h
#define VoxelGIVoxelView_h

#include "FramePlan.h"
#include "VoxelGrid.h"

class vtkOpenGLRenderWindow;

namespace voxelgi
{
class LightBlock;
class LightVoxels;
class ShadowMaps;
class VoxelMipmap;
class VoxelizePass;

struct VoxelView
{
  /// The window whose context holds the voxels (null before the owner's first frame).
  vtkOpenGLRenderWindow* Window = nullptr;
  /// The pass shares another pass's voxels itself (then it has none to share).
  bool Shares = false;
  /// The owner's last frame ran GI.
  bool Active = false;
  VoxelGrid Grid;
  /// Any voxelized actor is specular.
  bool AnySpecular = false;
  const VoxelizePass* Voxelization = nullptr;
  const LightVoxels* Lighting = nullptr;
  const VoxelMipmap* Mipmap = nullptr;
  /// The lights the voxels are lit with, and their shadow maps.
  const LightBlock* Lights = nullptr;
  const ShadowMaps* Shadows = nullptr;
  const RadianceState* Radiance = nullptr;
  /// The owner's last frame: its renderer and when it was presented.
  PresentedFrame Presented;
};

}

#endif
