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
class vtkProp;
class vtkProperty;
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
 *
 * An actor class that does not draw a mapper it is handed (vtkFollower, vtkLODActor,
 * vtkQuadricLODActor: they draw through an internal OpenGL actor, and vtkActor's own
 * Render(renderer, mapper) draws nothing) is drawn through a stand-in OpenGL actor with its
 * matrix (a follower's faces its camera), property, textures and property keys; so is an
 * actor that shows its edges or vertices or draws lines as tubes or points as spheres, with
 * a copy of its property that draws the surface alone.
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
  /// The actor that `drawn` (a prop a copy was drawn with) stands for: itself or the actor
  /// whose stand-in it is.
  vtkProp* Original(vtkProp* drawn) const;
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
    vtkSmartPointer<vtkActor> StandIn; // for actors that draw through an internal actor
    vtkSmartPointer<vtkProperty> Property; // the stand-in's, without edges, vertices, imposters
    vtkMTimeType PropertySynced = 0;
  };
  /// The actor's copy, its mapper up to date.
  Copy& CopyOf(vtkActor* actor);
  /// The actor that draws the copy: `actor` itself, or its stand-in, brought up to date.
  vtkActor* Drawing(Copy& copy, vtkActor* actor);
  void Erase(std::unordered_map<vtkActor*, Copy>::iterator it, vtkWindow* window);

  std::unordered_map<vtkActor*, Copy> Copies;
  std::unordered_map<vtkProp*, vtkActor*> StandIns; // stand-in -> the actor it stands for
};

}

#endif
