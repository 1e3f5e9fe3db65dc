#include "VoxelStages.h"

#include "Frame.h"
#include "LightBlock.h"
#include "Ranks.h"
#include "vtkVoxelGIPass.h"

#include "vtkOpenGLRenderWindow.h"

namespace voxelgi
{

void VoxelStages::Wire(Frame& frame) const
{
  frame.Voxelization = this->Voxelize;
  frame.Lighting = &this->Lighting;
  frame.Mipmap = &this->Mipmap;
  frame.Shadows = &this->Shadows;
  frame.Bounce = &this->Bounce;
}

bool VoxelStages::Relight(const Frame& frame, std::string& error, std::string& note)
{
  // The light block is bound by the caller; the grid block too.
  bool ok = true;
  // A rank's maps would see its own piece only; the raymarch sees the merged voxels. A
  // depth map holds no partial occupancy: with volumes, light is traced through the voxels.
  if (frame.Config.LightOcclusion == LIGHT_OCCLUSION_SHADOW_MAPS &&
    !frame.Processes->Distributed() && (!frame.Volumes || frame.Volumes->empty()))
  {
    ok = this->Shadows.Prepare(frame, error, note);
    if (ok)
    {
      this->Shadows.Run(frame);
    }
  }
  else
  {
    this->Shadows.ReleaseGraphicsResources(frame.Window);
  }
  ok = ok && this->Lighting.Prepare(frame, error) && this->Mipmap.Prepare(frame, error) &&
    (frame.Config.Bounces == 0 || this->Bounce.Prepare(frame, error));
  if (ok)
  {
    this->Lighting.Run(frame);
    this->Mipmap.Run(frame);
    if (frame.Config.Bounces > 0)
    {
      this->Bounce.Run(frame);
    }
  }
  return ok;
}

unsigned long long VoxelStages::AllocatedBytes(int resource) const
{
  switch (resource)
  {
    case vtkVoxelGIPass::RESOURCE_VOXELIZATION:
      return this->Voxelize->MemoryBytes() - this->Voxelize->EmissionBytes();
    case vtkVoxelGIPass::RESOURCE_EMISSION:
      return this->Voxelize->EmissionBytes();
    case vtkVoxelGIPass::RESOURCE_RADIANCE:
      return this->Lighting.GetRadiance().Bytes();
    case vtkVoxelGIPass::RESOURCE_DIRECT:
      return this->Lighting.GetDirect().Bytes();
    case vtkVoxelGIPass::RESOURCE_DIRECTIONAL:
      return this->Mipmap.MemoryBytes();
    case vtkVoxelGIPass::RESOURCE_SHADOW_MAPS:
      return this->Shadows.Bytes();
    case vtkVoxelGIPass::RESOURCE_SCENE_BUFFERS:
      return this->Voxelize->SceneBytes() +
        (this->Bounce.GetIncident() ? this->Bounce.GetIncident()->Bytes() : 0);
    default:
      return 0;
  }
}

unsigned long long VoxelStages::MemoryBytes() const
{
  return this->Voxelize->MemoryBytes() + this->Lighting.MemoryBytes() +
    this->Mipmap.MemoryBytes() + this->Shadows.Bytes();
}

void VoxelStages::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Voxelize->ReleaseGraphicsResources(window);
  this->Shadows.ReleaseGraphicsResources(window);
  this->Lighting.ReleaseGraphicsResources(window);
  this->Mipmap.ReleaseGraphicsResources(window);
  this->Bounce.ReleaseGraphicsResources(window);
}

}
