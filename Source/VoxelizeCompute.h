/**
 * VoxelizeCompute: voxelization by compute (voxelize.comp) from the actors' GPU-resident
 * triangles (SceneBuffers), into the accumulators and flag volume of the Voxelize stage, by the
 * rule the raster path applies through VTK's mappers. Two dispatches per actor (its triangles,
 * then those that cover many pixel columns, one work group each) and one barrier per pass,
 * where the raster path draws every actor through VTK's mapper and the raster pipeline.
 */
#ifndef VoxelGIVoxelizeCompute_h
#define VoxelGIVoxelizeCompute_h

#include "GLHelpers.h"
#include "SceneBuffers.h"

#include <array>
#include <string>
#include <vector>

class vtkActor;
class vtkWindow;

namespace voxelgi
{
struct Frame;

class VoxelizeCompute
{
public:
  /// An actor to voxelize: its buffers and emitted radiance.
  struct Item
  {
    vtkActor* Actor = nullptr;
    const SceneBuffers::Entry* Buffers = nullptr;
    std::array<double, 3> Emission{ { 0.0, 0.0, 0.0 } };
  };

  /// Build the program for the accumulators' variant (`defines`: VOXEL_CHANNELS).
  bool Prepare(const std::string& defines, std::string& error);
  /// The buffers of `actor`, brought up to date, when compute voxelization can read it; null
  /// when its mapper has to draw it (context current).
  const SceneBuffers::Entry* Read(vtkActor* actor);
  /// Voxelize `items` as static or dynamic actors into the bound accumulators.
  void Draw(const Frame& frame, const std::vector<Item>& items, bool staticPass);
  /// Free the buffers of actors that are not in `records`.
  void Retain(const std::vector<ActorRecord>& records) { this->Buffers.Retain(records); }
  /// GPU memory of the actors' buffers and the lists.
  std::size_t MemoryBytes() const;
  void ReleaseGraphicsResources();

private:
  GLProgram Program;
  SceneBuffers Buffers;
  StorageBuffer Large; // per item (groups, 1, 1, count), then the items' lists
};

}

#endif
