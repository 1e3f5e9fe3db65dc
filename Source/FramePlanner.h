/**
 * The frame planner: builds the frame's plan (FramePlan.h) from the ranks' agreement, the
 * scan, the lights, the settings and a voxel source, and keeps what it compares the frame
 * with: the scan's records, the light block and the frame history. The pass asks it for the
 * plan at the start of a frame and tells it what the frame presented at the end.
 */
#ifndef VoxelGIFramePlanner_h
#define VoxelGIFramePlanner_h

#include "FramePlan.h"
#include "LightBlock.h"
#include "SceneScan.h"

#include "vtkType.h" // for vtkMTimeType

#include <string>

namespace voxelgi
{
struct Frame;
struct VoxelView;
class Gate;
class Ranks;

class FramePlanner
{
public:
  FramePlanner(Gate& gate, Ranks& ranks)
    : Notices(gate)
    , Processes(ranks)
  {
  }

  /// The ranks' part of the plan (a collective call when distributed): whether every rank
  /// runs GI (`admitted` on this one), the scan, and what the Voxelize stage does. Fills the
  /// frame's grid, actors and specularity.
  bool PlanVoxels(Frame& frame, bool admitted);
  /// The plan from the pass's own voxels (`emission`: they have emissive voxels, or will):
  /// the lights, the radiance, the trace.
  bool PlanLights(Frame& frame, bool emission, vtkMTimeType settingsTime);
  /// The plan from a voxel source's voxels: this renderer's lights, the trace; false (said
  /// once) where the source cannot be followed (it shares voxels itself, or renders into
  /// another window).
  bool PlanSource(Frame& frame, const VoxelView& source, vtkMTimeType settingsTime);

  /// The Voxelize stage rewrote the voxels as the plan said.
  void Voxelized(const Frame& frame);
  /// The relight ran (`valid`) or could not; `note` (if any) is said as a warning.
  void Lit(const Frame& frame, bool valid, const std::string& note);
  /// The frame is drawn: with a traced image (`traced`) or not.
  void Presented(const Frame& frame, bool traced, vtkMTimeType settingsTime);
  /// The voxels and what was made from them are gone: the next frame rebuilds all.
  void Forget();
  /// The last frame Presented() was told of.
  const PresentedFrame& LastPresented() const { return this->Last; }

  SceneScan Scan;
  LightBlock Lights;
  FrameHistory History;

private:
  /// Gather the renderer's lights into the light block; false (said once) when neither they
  /// nor `emission` light anything. `changed`: the lights differ from the last frame's.
  bool GatherLights(Frame& frame, bool emission, bool& changed);
  void PlanTrace(Frame& frame, bool lightsReset, vtkMTimeType settingsTime);

  Gate& Notices;
  Ranks& Processes;
  PresentedFrame Last;
};

}

#endif
