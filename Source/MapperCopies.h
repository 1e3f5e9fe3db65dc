/**
 * MapperCopies: a copy of each actor's mapper for a stage that draws the actors with shader
 * code of its own (voxelization, shadow maps).
 */
#ifndef VoxelGIMapperCopies_h
#define VoxelGIMapperCopies_h

#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkType.h"         // for vtkMTimeType
#include "vtkWeakPointer.h"  // for vtkWeakPointer

#include <unordered_map>
#include <vector>

class vtkActor;
class vtkMapper;
class vtkRenderer;
class vtkWindow;

namespace voxelgi
{
struct ActorRecord;

/**
 * VTK 9.1's polydata mapper rebuilds its shader source (string substitution, hashing, cache
 * look-up) whenever the render passes in the actor's keys or the renderer's lights differ
 * from its last draw (vtkOpenGLPolyDataMapper::GetRenderPassStageMTime). Drawing the user's
 * mappers in the G-buffer and again for voxelization and shadow maps rebuilt every mapper's
 * shaders two or three times in each frame that voxelized. A copy (same class, same input
 * connection, same colouring settings, drawn with the user's actor: its property, textures
 * and matrix) only ever draws for one stage, so neither it nor the user's mapper rebuilds;
 * vertex buffers of the same arrays are shared through the window's VBO cache.
 */
class MapperCopies
{
public:
  MapperCopies() = default;
  ~MapperCopies();
  MapperCopies(const MapperCopies&) = delete;
  MapperCopies& operator=(const MapperCopies&) = delete;

  /// Draw `actor` as its RenderOpaqueGeometry() would, with the copy of its mapper, into
  /// `renderer`. Returns 1 when something was drawn.
  int Draw(vtkActor* actor, vtkRenderer* renderer);
  /// Free the copies of actors that are not in `records` (the context current).
  void Retain(const std::vector<ActorRecord>& records, vtkWindow* window);
  /// Free every copy's GL objects and the copies (the context current).
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  struct Copy
  {
    vtkWeakPointer<vtkActor> Actor;
    vtkWeakPointer<vtkMapper> Source;
    vtkSmartPointer<vtkMapper> Mapper;
    vtkMTimeType Synced = 0;
  };
  /// The up-to-date copy of the actor's mapper.
  vtkMapper* CopyOf(vtkActor* actor);

  std::unordered_map<vtkActor*, Copy> Copies;
};

}

#endif
