#include "VoxelGridBlock.h"

#include "VoxelGrid.h"
#include "shader_interface.h"

namespace voxelgi
{

void VoxelGridBlock::Bind(const VoxelGrid& grid)
{
  Block block{};
  block.voxelResolution = grid.Resolution;
  block.voxelSize = static_cast<float>(grid.VoxelSize);
  if (!this->Buffer.IsAllocated() || block.voxelResolution != this->Uploaded.voxelResolution ||
    block.voxelSize != this->Uploaded.voxelSize)
  {
    if (!this->Buffer.IsAllocated())
    {
      this->Buffer.Allocate(sizeof(Block));
    }
    this->Buffer.Upload(&block, sizeof(Block));
    this->Uploaded = block;
  }
  this->Buffer.BindUniform(VOXELGI_GRID_BLOCK_BINDING);
}

void VoxelGridBlock::ReleaseGraphicsResources(vtkWindow*)
{
  this->Buffer.Release();
}

}
