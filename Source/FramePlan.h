/**
 * The frame plan: what each stage of vtkVoxelGIPass does this frame and why, decided once at
 * the start of the frame from the scan, the lights, the settings, the ranks' agreement and a
 * voxel source. Stages read it (through the Frame); nothing else keeps "what changed" state.
 *
 * FrameHistory is the plan's memory: what the last frames produced (the voxels' generation,
 * what the radiance was lit from, what the traced image shows). Comparing the frame with it
 * gives the plan; a stage that ran tells it what it produced.
 */
#ifndef VoxelGIFramePlan_h
#define VoxelGIFramePlan_h

#include "SceneScan.h"

#include "vtkRenderer.h"    // for vtkWeakPointer<vtkRenderer>
#include "vtkType.h"        // for vtkMTimeType
#include "vtkWeakPointer.h" // for vtkWeakPointer

#include <vector>

namespace voxelgi
{
struct Settings;

/// What the radiance (voxel light, mipmaps, bounces) gets this frame.
enum class LightWork
{
  Current,  ///< it is up to date: nothing runs
  Relight,  ///< voxels, lights or settings changed: light and bounce anew
  Continue, ///< only camera lights turned: relight, one bounce on from the last indirect light
  Progress, ///< lights or voxels changed in an interactive render: relight, one bounce on from
            ///< the last indirect light; the next still frame converges (InteractiveBounces)
};

/// What the per-pixel stages do this frame.
enum class TraceWork
{
  Present,    ///< nothing the image shows changed: present the last one again
  CameraOnly, ///< only the camera moved: the trace may reuse the last frame's results
  Full,       ///< trace every pixel
};

struct FramePlan
{
  /// GI runs this frame (else VTK's image alone). A stage that cannot run turns it off.
  bool GI = false;
  /// The scan's decision for the voxels: none, the dynamic actors, or all (Voxelize).
  VoxelUpdate Voxels;
  /// The ranks' part of the frame (scan, voxelize) ran ahead of Render(), at the frame's
  /// start (vtkVoxelGIPass::RenderRanks).
  bool RanAhead = false;
  LightWork Lights = LightWork::Current;
  TraceWork Trace = TraceWork::Full;
  /// A voxel debug view replaces the trace: VTK's image with the voxels over it.
  bool VoxelView = false;
  /// Bounces the relight runs (Continue, Progress: one).
  int Bounces = 0;
};

/// What a pass whose voxels are traced has produced: read by a pass that shares them.
struct RadianceState
{
  /// Counts the relights a trace cannot reuse.
  unsigned long long Generation = 0;
};

/// A pass's last frame: its renderer (null once deleted) and when it was presented, on VTK's
/// modification clock (0: never). A pass that shares the voxels asks whether they are of this
/// render of the window.
struct PresentedFrame
{
  vtkWeakPointer<vtkRenderer> Renderer;
  vtkMTimeType Time = 0;
};

class FrameHistory
{
public:
  /// The voxels were rewritten.
  void VoxelsWritten() { ++this->VoxelGeneration; }

  /// What the radiance gets: whether the voxels change this frame (`voxelsChange`) or
  /// changed since it was lit, the lights (`lightsChanged` since it was lit, the camera
  /// lights' `turn` since then, infinite when other lights changed), `settings`, the `grid`
  /// and whether VTK renders interactively (`interactive`: InteractiveBounces applies).
  LightWork PlanLights(bool voxelsChange, bool lightsChanged, double turn,
    const Settings& settings, const VoxelGrid& grid, bool interactive) const;
  /// The radiance was lit (Relight, Continue, Progress) for `settings` and `grid`; `valid`:
  /// false when it could not be (it is stale then).
  void Lit(LightWork work, bool valid, const Settings& settings, const VoxelGrid& grid);
  /// The radiance this history's voxels have, for passes sharing them.
  const RadianceState& GetRadiance() const { return this->Radiance; }

  /// What the trace does: `radiance` is the state of the traced radiance (this pass's or a
  /// voxel source's), `lightsReset` whether this renderer's lights changed other than by
  /// turning with the camera, `settingsTime` the pass's settings' time, `imageKey` what the
  /// image shows now (SceneScan::ImageKey).
  TraceWork PlanTrace(const RadianceState& radiance, bool lightsReset, vtkMTimeType settingsTime,
    const std::vector<unsigned long long>& imageKey) const;
  /// The frame presented a traced image of `radiance` with these settings, showing
  /// `imageKey` (read after VTK drew it).
  void Traced(const RadianceState& radiance, vtkMTimeType settingsTime,
    std::vector<unsigned long long> imageKey);
  /// The frame presented no traced image: the next one traces everything.
  void NotTraced() { this->HasImage = false; }
  /// Whether the last frame presented a traced image (its images can be read back).
  bool HasTracedImage() const { return this->HasImage; }

  /// Everything is gone (resources released): the next frame rebuilds all.
  void Forget();

private:
  unsigned long long VoxelGeneration = 0;
  // What the radiance was lit from: the voxels' generation and the settings it depends on.
  bool LitValid = false;
  bool LitPartly = false; // by a Progress: a still frame converges it
  unsigned long long LitVoxels = 0;
  std::vector<double> LitKey;
  RadianceState Radiance;
  // What the last traced image shows.
  bool HasImage = false;
  unsigned long long ImageRadiance = 0;
  vtkMTimeType ImageSettings = 0;
  std::vector<unsigned long long> ImageKey;
};

}

#endif
