/**
 * SceneBuffers: the GPU-resident copy of the actors that compute voxelization (voxelize.comp)
 * and the shadow maps (shadow_depth.vert) read. Per actor, the vertex positions of its surface
 * triangles (relative to a shift, so that data far from the origin stays exact in floats),
 * their scalar colours, the triangles' vertex indices and their cell colours, uploaded when
 * the actor's data or colouring changes (its input's or its mapper's time, which covers the
 * lookup table); transforms and materials are read at each draw. An actor VTK draws some other way keeps the raster path
 * through its mapper (ComputeUnreadable says why).
 */
#ifndef VoxelGISceneBuffers_h
#define VoxelGISceneBuffers_h

#include "GLHelpers.h"

#include "vtkType.h"        // for vtkMTimeType
#include "vtkWeakPointer.h" // for vtkWeakPointer

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

class vtkActor;
class vtkPolyData;

namespace voxelgi
{
struct ActorRecord;

/// How an actor's triangles are coloured, as voxelize.comp's voxelColorMode.
enum class TriangleColors
{
  Actor = 0,  ///< the property's diffuse colour
  Vertex = 1, ///< the mapper's colours per point, interpolated
  Cell = 2    ///< the mapper's colours per cell
};

/// An actor's surface triangles as voxelize.comp reads them.
struct TriangleArrays
{
  struct Vertex
  {
    float Position[3]; // relative to Shift
    std::uint32_t Color; // RGBA8, red in the low byte
  };
  std::vector<Vertex> Vertices;
  std::vector<std::uint32_t> Indices;    // three vertex indices per triangle
  std::vector<std::uint32_t> CellColors; // RGBA8 per triangle: per-cell colouring only
  std::array<double, 3> Shift{ { 0.0, 0.0, 0.0 } };
  TriangleColors Colors = TriangleColors::Actor;
};

/// Why compute voxelization cannot read `actor` (empty: it can): what its mapper or property
/// would draw differently from plain surface triangles.
std::string ComputeUnreadable(vtkActor* actor);

/// Read the surface triangles of `actor`'s polydata as VTK's mapper draws them (polygons as
/// fans, strips as alternating triangles; triangles with an index beyond the points are left
/// out), coloured by the mapper's own mapping, into `arrays` (whose memory is reused). False
/// with `why` when the colours come from field data, which VTK applies in ways the buffers do
/// not hold.
bool ReadTriangles(vtkActor* actor, vtkPolyData* input, TriangleArrays& arrays, std::string& why);

class SceneBuffers
{
public:
  /// One actor's buffers.
  struct Entry
  {
    vtkWeakPointer<vtkActor> Actor;
    vtkPolyData* Input = nullptr; // identity only, never dereferenced
    vtkMTimeType InputTime = 0;
    vtkMTimeType MapperTime = 0;
    double Opacity = 1.0; // the actor's, in the scalar colours' alpha
    StorageBuffer Vertices;
    StorageBuffer Indices;    // also the element buffer of the shadow maps' draws
    StorageBuffer CellColors; // per-cell colouring only
    unsigned int TriangleCount = 0;
    std::array<double, 3> Shift{ { 0.0, 0.0, 0.0 } };
    TriangleColors Colors = TriangleColors::Actor;
  };

  /// The buffers of `actor` (ComputeUnreadable empty), read and uploaded again when its data or
  /// colouring changed; null with `why` when it cannot be read (context current).
  const Entry* Update(vtkActor* actor, std::string& why);
  /// Free the buffers of actors that are not in `records`.
  void Retain(const std::vector<ActorRecord>& records);
  /// GPU memory the buffers hold.
  std::size_t MemoryBytes() const;
  void ReleaseGraphicsResources();

private:
  using Map = std::unordered_map<vtkActor*, Entry>;
  /// Release the entry's buffers (context current) and remove it.
  Map::iterator Erase(Map::iterator it);

  Map Entries;
  TriangleArrays Scratch; // the last read, kept for its memory
};

}

#endif
