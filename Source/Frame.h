/**
 * What every stage of vtkVoxelGIPass sees of one frame: the renderer and its window, the
 * render state VTK passed in, the frame's plan, the voxel grid, a snapshot of the pass's
 * settings, and the stage clock. Every stage has one shape: `Prepare(const Frame&, error)`
 * (allocate what the frame needs, build programs; false with a message when it cannot),
 * `Run(const Frame&)` (do the work, timed under the stage's own id),
 * `ReleaseGraphicsResources(vtkWindow*)` (free every GL object, context current).
 */
#ifndef VoxelGIFrame_h
#define VoxelGIFrame_h

#include "FramePlan.h"
#include "GLHelpers.h"
#include "SceneScan.h"
#include "StageIds.h"
#include "SettingsSnapshot.h" // voxelgi::Settings, generated from VoxelGISettings.json
#include "VoxelGrid.h"

#include "vtkIndent.h" // for vtkIndent

#include <array>
#include <string>

class vtkOpenGLRenderWindow;
class vtkRenderPass;
class vtkRenderState;
class vtkRenderer;
class vtkVoxelGIPassSettings;

namespace voxelgi
{
class LightBlock;
class LightVoxels;
class Ranks;
class ShadowMaps;
class VoxelBounce;
class VoxelMipmap;
class VoxelizePass;

/// The pass's settings now; HardwareConservativeRaster only where the context has it, capped
/// to the software profile where it applies.
Settings Snapshot(vtkVoxelGIPassSettings* pass, bool hasConservativeRaster, bool softwareProfile);

/// Which stages ran in a frame and, with timing on, their GPU (or, for the scan, CPU) time.
class StageClock
{
public:
  void Reset();
  void Begin(int stage);
  void End(int stage);
  /// Record a CPU-measured stage.
  void SetCpuTime(int stage, double milliseconds);
  /// Collect the GPU times of the stages that ran (waits for the GPU).
  void Resolve();
  /// Whether `stage` (StageIds.h) ran, and its time (false and 0 out of range).
  bool Ran(int stage) const;
  double Milliseconds(int stage) const;
  /// Which stages ran, with their times when timing is on.
  void Print(ostream& os, vtkIndent indent) const;
  void SetTiming(bool on) { this->Timing = on; }
  void ReleaseGraphicsResources();

private:
  bool Timing = false;
  std::array<StageTimer, stage::Count> Timers;
  std::array<bool, stage::Count> DidRun{};
  std::array<double, stage::Count> Times{};
};

/// Marks a stage as run and times it, for the lifetime of the object.
class ScopedStage
{
public:
  ScopedStage(StageClock& clock, int stage)
    : Clock(clock)
    , Stage(stage)
  {
    clock.Begin(stage);
  }
  ~ScopedStage() { this->Clock.End(this->Stage); }
  ScopedStage(const ScopedStage&) = delete;
  ScopedStage& operator=(const ScopedStage&) = delete;

private:
  StageClock& Clock;
  int Stage;
};

struct Frame
{
  vtkRenderer* Renderer = nullptr;
  vtkOpenGLRenderWindow* Window = nullptr;
  /// When the window's current render and the one before started (WindowFollower).
  std::array<vtkMTimeType, 2> RenderStarts{ { 0, 0 } };
  const vtkRenderState* State = nullptr;
  /// The pass that renders VTK's own image (vtkVoxelGIPass's delegate).
  vtkRenderPass* Delegate = nullptr;
  /// The ranks of a distributed render, whose voxels are merged (one process: not
  /// Distributed()).
  Ranks* Processes = nullptr;
  Settings Config;
  StageClock* Clock = nullptr;
  /// What each stage does this frame.
  FramePlan Plan;
  /// The actors and volumes the voxels are built from.
  const std::vector<ActorRecord>* Actors = nullptr;
  const std::vector<VolumeRecord>* Volumes = nullptr;
  /// The renderer's lights, as the light block holds them.
  const LightBlock* Lights = nullptr;
  /// The grid of the current voxels.
  VoxelGrid Grid;
  /// The volumes the trace and the debug view read: the pass's own, or those of the pass
  /// whose voxels it shares (vtkVoxelGIPass::SetVoxelSource).
  const VoxelizePass* Voxelization = nullptr;
  const LightVoxels* Lighting = nullptr;
  const VoxelMipmap* Mipmap = nullptr;
  /// The bounce, whose light arriving at the volumes' voxels VTK's volume shading adds
  /// (VolumeLighting).
  const VoxelBounce* Bounce = nullptr;
  /// The lights' shadow maps, where the pixels' shadows may use them (the pass's own lights
  /// and voxels); else null.
  const ShadowMaps* Shadows = nullptr;
  /// The state of the radiance traced (the pass's own, or its voxel source's).
  const RadianceState* Radiance = nullptr;
  /// Whether the renderer has lights GI uses (else lit surfaces show only their ambient term).
  bool LitScene = true;
  /// Whether any voxelized actor is specular (else no specular cone).
  bool AnySpecular = false;
  /// The renderer's viewport in the window (tiled size and origin).
  int Width = 0;
  int Height = 0;
  int X = 0;
  int Y = 0;
};

}

#endif
