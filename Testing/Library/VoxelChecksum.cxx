#include "VoxelChecksum.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkVoxelGIPass.h"

#include <cstddef>
#include <cstdint>

namespace voxelgi
{
int VoxelAlbedoChecksum(vtkVoxelGIPass* gi)
{
  vtkNew<vtkImageData> albedo;
  if (!gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, albedo))
  {
    return 0;
  }
  vtkDataArray* voxels = albedo->GetPointData()->GetScalars();
  const auto* bytes = static_cast<const unsigned char*>(voxels->GetVoidPointer(0));
  const std::size_t count =
    static_cast<std::size_t>(voxels->GetNumberOfValues()) * voxels->GetDataTypeSize();
  std::uint32_t hash = 2166136261u;
  for (std::size_t i = 0; i < count; ++i)
  {
    hash = (hash ^ bytes[i]) * 16777619u;
  }
  return static_cast<int>(hash & 0x7fffffffu);
}
}
