/**
 * VolumeVoxels: the renderer's volumes (vtkVolume on vtkImageData, one scalar component,
 * composite blending) resampled into the voxel grid (voxelize_volume.comp), so that they cast
 * soft shadows and ambient occlusion, stop indirect light and scatter it with their colour
 * (not the lights' direct light: VTK shows volumes unlit, light_voxels.comp).
 * Each volume's scalars go through its colour and scalar-opacity transfer functions into a
 * grid-sized volume of partial occupancy (rgb colour, a the share of light a voxel stops,
 * from the opacity per ScalarOpacityUnitDistance), which the resolve merges into the voxels
 * where no surface is. A volume's scalars are uploaded when its data changes, its transfer
 * functions when its property changes; nothing is resampled when no volume and not the grid
 * changed, and a scene without volumes holds nothing for them.
 *
 * Left out (said by the scan's notice): other inputs than image data, several components,
 * cell scalars, blend modes other than composite. Gradient opacity and shading do not change
 * the occupancy.
 */
#ifndef VoxelGIVolumeVoxels_h
#define VoxelGIVolumeVoxels_h

#include "GLHelpers.h"
#include "VoxelGrid.h"

#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkType.h"         // for vtkMTimeType
#include "vtkVolume.h"       // for the records' comparison
#include "vtkWeakPointer.h"  // for vtkWeakPointer

#include <cstddef>
#include <string>
#include <vector>

class vtkTextureObject;
class vtkWindow;

namespace voxelgi
{
struct Frame;

/// What the scan remembers of a volume between frames.
struct VolumeRecord
{
  vtkWeakPointer<vtkVolume> Volume;
  vtkMTimeType Signature = 0; // latest modification time of volume, property, mapper, input

  bool operator==(const VolumeRecord& other) const
  {
    return this->Volume == other.Volume && this->Signature == other.Signature;
  }
};

class VolumeVoxels
{
public:
  VolumeVoxels();
  ~VolumeVoxels();
  VolumeVoxels(const VolumeVoxels&) = delete;
  VolumeVoxels& operator=(const VolumeVoxels&) = delete;

  /// Why `volume` cannot be resampled into the voxels (empty: it can). GL-free.
  static std::string LeftOutReason(vtkVolume* volume);

  /// Allocate the grid-sized volume when the frame's update has volumes, else free
  /// everything.
  bool Prepare(const Frame& frame, std::string& error);
  /// Resample the frame's volumes into the grid when any of them or the grid changed.
  void Run(const Frame& frame);
  /// The resampled volumes (rgb colour, a occupancy); null without volumes.
  const Volume3D* GetGrid() const { return this->Grid.IsAllocated() ? &this->Grid : nullptr; }
  /// GPU memory of the grid-sized volume and the volumes' scalars and transfer functions.
  std::size_t MemoryBytes() const;
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  struct Source;
  /// The up-to-date textures of `volume` (context current).
  Source& Upload(const Frame& frame, vtkVolume* volume);
  /// Resample one volume; `first` overwrites the whole grid, later ones add to it.
  void Resample(const Frame& frame, vtkVolume* volume, Source& source, bool first);

  Volume3D Grid;
  GLProgram Program;
  std::vector<Source> Sources;
  std::vector<VolumeRecord> Built; // what the grid holds
  VoxelGrid BuiltGrid;
};

}

#endif
