/**
 * PropReader: what the scan reads of each view prop every frame (its bounds, its signature,
 * why VTK renders it without GI), kept between frames. VTK's frustum culler has already
 * brought every visible prop's pipeline up to date before the render pass runs (it asks each
 * prop for its bounds); a plain actor whose signature is unchanged since the last reading
 * then has the bounds read then, and reading them again would update its pipeline a second
 * time, the largest cost of a camera-only frame with many actors. Other props (followers
 * turn with the camera, slices and volumes have their own bounds), and renderers without
 * that culler, are read in full every frame. GL-free.
 */
#ifndef VoxelGIPropReader_h
#define VoxelGIPropReader_h

#include "vtkType.h" // for vtkMTimeType

#include <cstddef>
#include <string>
#include <vector>

class vtkActor;
class vtkDataObject;
class vtkProp;
class vtkRenderer;

namespace voxelgi
{

/// Whether `data` (a polydata, or a composite of them) holds no polygons or strips, only
/// vertices and lines; other datasets have surfaces.
bool PointsAndLinesOnly(vtkDataObject* data);

/// What the scan reads of one view prop.
struct PropReading
{
  vtkProp* Prop = nullptr;
  vtkMTimeType Signature = 0; // PropSignature()
  vtkMTimeType InputTime = 0; // the first input's modification time
  bool HasBounds = false;     // visible, with initialized bounds
  double Bounds[6] = {};
  std::string LeftOut;    // why it is not voxelized (empty: it is, or it has no bounds)
  bool Translucent = false; // an actor VTK draws in its translucent step (voxelized with
                            // partial occupancy; its shadows pass part of the light)
};

class PropReader
{
public:
  /// Start reading the view props of `renderer`, in order; `inRender`: inside its Render(),
  /// after its cullers ran (else every prop is read in full).
  void Begin(vtkRenderer* renderer, bool inRender);
  /// Read the next view prop.
  const PropReading& Read(vtkProp* prop);
  /// Forget the readings of props past the ones read since Begin().
  void End();

  /// Latest modification time of an actor and of what it is drawn from: its mapper, every
  /// input of the mapper, the planes it clips with, its textures' images and its shader
  /// uniforms (the first input's own time into `inputTime`, when given).
  static vtkMTimeType ActorSignature(vtkActor* actor, vtkMTimeType* inputTime = nullptr);
  /// A prop's signature for the image key: actors as above, images and volumes with their
  /// mappers' inputs, other props (overlays) by their own time.
  static vtkMTimeType PropSignature(vtkProp* prop, vtkMTimeType* inputTime = nullptr);

  /// The signature of `prop` after VTK drew it, given the one read before the draw
  /// (`scanned`): drawing modifies at most the actor and its mapper (a default lookup table),
  /// which are read again; other props are read in full.
  static vtkMTimeType DrawnSignature(vtkProp* prop, vtkMTimeType scanned);

private:
  /// Read `prop` in full into `reading`: its bounds (updating its pipeline) first.
  static void ReadAll(vtkProp* prop, PropReading& reading);

  std::vector<PropReading> Readings; // by position among the view props
  std::size_t Next = 0;
  bool Culled = false; // VTK's culler asked the visible props for their bounds this frame
};

}

#endif
