#include "VoxelGridBlock.h"

#include "VoxelGrid.h"
#include "shader_interface.h"

#include <cstring>

namespace voxelgi
{

void VoxelGridBlock::Bind(const VoxelGrid& grid)
{
  Block block{};
  block.voxelResolution = grid.Resolution;
  block.voxelSize = static_cast<float>(grid.VoxelSize);
  glm::dvec3 lo, hi;
  grid.SceneVoxels(lo, hi);
  for (int a = 0; a < 3; ++a)
  {
    block.voxelSceneLo[a] = static_cast<float>(lo[a]);
    block.voxelSceneHi[a] = static_cast<float>(hi[a]);
  }
  if (!this->Buffer.IsAllocated() || std::memcmp(&block, &this->Uploaded, sizeof(Block)) != 0)
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
