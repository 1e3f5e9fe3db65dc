/**
 * The stages that make the voxels and their light, wired to what they read: Voxelize, the
 * grid block, ShadowMaps, LightVoxels, VoxelMipmap and VoxelBounce, with their memory and
 * release. Relight runs the light's part as the frame plan says.
 */
#ifndef VoxelGIVoxelStages_h
#define VoxelGIVoxelStages_h

#include "LightVoxels.h"
#include "ShadowMaps.h"
#include "VoxelBounce.h"
#include "VoxelGridBlock.h"
#include "VoxelMipmap.h"
#include "VoxelizePass.h"

#include "vtkNew.h" // for vtkNew

#include <string>

class vtkWindow;

namespace voxelgi
{
struct Frame;

struct VoxelStages
{
  vtkNew<VoxelizePass> Voxelize;
  VoxelGridBlock GridBlock;
  ShadowMaps Shadows{ *Voxelize };
  LightVoxels Lighting{ *Voxelize, Shadows };
  VoxelMipmap Mipmap{ *Voxelize, Lighting };
  VoxelBounce Bounce{ *Voxelize, Lighting, Mipmap };

  /// Point the frame at these stages' volumes, maps and lights.
  void Wire(Frame& frame) const;
  /// ShadowMaps (scene lights, one process), LightVoxels, Mipmap and Bounce; false with
  /// `error` when one cannot be prepared; `note` says what was made smaller than asked.
  bool Relight(const Frame& frame, std::string& error, std::string& note);
  /// GPU memory of one kind of resource (vtkVoxelGIPass::Resources), and of all.
  unsigned long long AllocatedBytes(int resource) const;
  unsigned long long MemoryBytes() const;
  void ReleaseGraphicsResources(vtkWindow* window);
};

}

#endif
