// A fingerprint of a pass's voxels, to compare the voxels of several passes, processes or runs
// without keeping their volumes.
#ifndef VoxelGIVoxelChecksum_h
#define VoxelGIVoxelChecksum_h

#include "vtkTestingVoxelGIModule.h" // for export macro

class vtkVoxelGIPass;

namespace voxelgi
{
// 31 bits of the FNV-1a hash of the bytes of the pass's voxel albedo volume, read back
// through its GetVoxelVolume(VOLUME_ALBEDO, ...) (which makes its window current); 0 when
// it has none.
VTKTESTINGVOXELGI_EXPORT int VoxelAlbedoChecksum(vtkVoxelGIPass* gi);
}

#endif
