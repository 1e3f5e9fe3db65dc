#include "FramePlanner.h"

#include "Frame.h"
#include "Gate.h"
#include "Ranks.h"
#include "VoxelView.h"
#include "VoxelizePass.h"
#include "StageIds.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkRendererCollection.h"
#include "vtkTimeStamp.h"

#include <algorithm>
#include <cmath>

namespace voxelgi
{
namespace
{
// Where `renderer` draws in a render of `window`: VTK draws layer by layer, each in the order
// the renderers were added (-1: not in the window).
long DrawOrder(vtkRenderWindow* window, vtkRenderer* renderer)
{
  vtkRendererCollection* renderers = window->GetRenderers();
  const long count = renderers->GetNumberOfItems();
  for (long i = 0; i < count; ++i)
  {
    if (renderers->GetItemAsObject(static_cast<int>(i)) == renderer)
    {
      return renderer->GetLayer() * count + i;
    }
  }
  return -1;
}

// Whether a source's voxels are of this render of the window: presented in it when the
// source draws first, else in the render before (a sharer drawn before its source traces
// the voxels of the source's last frame).
bool Current(const Frame& frame, const PresentedFrame& source)
{
  const long order = source.Renderer ? DrawOrder(frame.Window, source.Renderer) : -1;
  return order >= 0 &&
    source.Time >
    frame.RenderStarts[order < DrawOrder(frame.Window, frame.Renderer) ? 0 : 1];
}
}


bool FramePlanner::PlanVoxels(Frame& frame, bool admitted)
{
  // Every rank voxelizes its piece into one grid: either all run GI, or none.
  const bool all = this->Processes.BeginFrame(admitted);
  if (admitted && !all)
  {
    this->Notices.Error(Gate::OtherRank,
      "Voxel GI is off on every rank: another of the " +
        std::to_string(this->Processes.Count()) +
        " ranks cannot run it (that rank says why). Rendering without GI.");
  }
  else
  {
    this->Notices.Clear(Gate::OtherRank);
  }
  if (!all)
  {
    return false;
  }
  ScanMessages messages;
  const bool ok =
    this->Scan.Scan(frame.Renderer, frame.Config, this->Processes, frame.Plan.Voxels, messages,
      frame.State != nullptr);
  frame.Clock->SetCpuTime(stage::Scan, this->Scan.GetMilliseconds());
  for (const std::string& warning : messages.Warnings)
  {
    this->Notices.Report(warning, false);
  }
  if (!messages.Error.empty())
  {
    this->Notices.Report(messages.Error, true);
  }
  frame.Actors = &this->Scan.GetRecords();
  frame.Volumes = &this->Scan.GetVolumes();
  frame.Grid = frame.Plan.Voxels.Run ? frame.Plan.Voxels.Grid : this->Scan.GetGrid();
  frame.AnySpecular = this->Scan.GetAnySpecular();
  return ok;
}

bool FramePlanner::PlanLights(Frame& frame, bool emission, vtkMTimeType settingsTime)
{
  FramePlan& plan = frame.Plan;
  bool changed = false;
  if (!this->GatherLights(frame, emission, changed))
  {
    this->History.Lit(LightWork::Relight, false, frame.Config, frame.Grid);
    return false;
  }
  const double turn = changed ? this->Lights.CameraTurnSinceLit() : 0.0;
  // VTK's interactor styles raise the window's desired update rate while the mouse drags
  // (15 frames/s by default) and drop it for the still frame after (0.0001).
  const bool interactive =
    frame.Config.InteractiveBounces && frame.Window->GetDesiredUpdateRate() >= 1.0;
  plan.Lights = this->History.PlanLights(
    plan.Voxels.Run && !plan.RanAhead, changed, turn, frame.Config, frame.Grid, interactive);
  // After a camera light's turn, or a change while VTK renders interactively, the new direct
  // light plus the last bounces' indirect light is close to the converged radiance: one
  // bounce from it stands for the whole chain.
  const bool onward = plan.Lights == LightWork::Continue || plan.Lights == LightWork::Progress;
  plan.Bounces = onward ? std::min(1, frame.Config.Bounces) : frame.Config.Bounces;
  frame.Radiance = &this->History.GetRadiance();
  this->PlanTrace(frame, false, settingsTime);
  return true;
}

bool FramePlanner::PlanSource(Frame& frame, const VoxelView& source, vtkMTimeType settingsTime)
{
  const char* error = source.Shares
    ? "its VoxelSource shares another pass's voxels itself"
    : (source.Window && source.Window != frame.Window
          ? "its VoxelSource renders into another window (voxels stay in their window's context)"
          : nullptr);
  if (error)
  {
    this->Notices.Error(
      Gate::Source, std::string("Voxel GI cannot run: ") + error + ". Rendering without GI.");
    return false;
  }
  this->Notices.Clear(Gate::Source);
  if (source.Presented.Time != 0 && !Current(frame, source.Presented))
  {
    this->Notices.Error(Gate::SourceGone,
      "Voxel GI cannot run: its VoxelSource did not render in this window's last frame (its "
      "renderer was removed or not drawn, or the source pass left it): its voxels are stale. "
      "Rendering without GI.");
    return false;
  }
  this->Notices.Clear(Gate::SourceGone);
  // The source says why when it has no GI; before its first frame there is nothing to trace.
  bool changed = false;
  if (!source.Active || !source.Window ||
    !this->GatherLights(frame, source.Voxelization->HasEmission(), changed))
  {
    return false;
  }
  frame.Grid = source.Grid;
  frame.AnySpecular = source.AnySpecular;
  frame.Voxelization = source.Voxelization;
  frame.Lighting = source.Lighting;
  frame.Mipmap = source.Mipmap;
  // The source's shadow maps are of its lights: they serve this renderer's pixels when it
  // has the same lights (viewports on one scene), else its shadows are traced.
  frame.Shadows =
    this->Lights.GetLights() == source.Lights->GetLights() ? source.Shadows : nullptr;
  frame.Radiance = source.Radiance;
  // This renderer's lights shade VTK's image and aim the shadow cones; the voxels are lit by
  // the source's. Camera lights turning with this camera make a camera move.
  const bool reset = changed && !std::isfinite(this->Lights.CameraTurnSinceLit());
  this->Lights.MarkLit();
  this->PlanTrace(frame, reset, settingsTime);
  return true;
}

void FramePlanner::PlanTrace(Frame& frame, bool lightsReset, vtkMTimeType settingsTime)
{
  FramePlan& plan = frame.Plan;
  // A relight changes the radiance: the whole image is traced again.
  plan.Trace = plan.Lights == LightWork::Relight || plan.Lights == LightWork::Progress
    ? TraceWork::Full
    : this->History.PlanTrace(*frame.Radiance, lightsReset, settingsTime,
        this->Scan.ImageKey(frame.Renderer, settingsTime, true));
}

bool FramePlanner::GatherLights(Frame& frame, bool emission, bool& changed)
{
  std::vector<std::string> warnings;
  changed = this->Lights.Gather(frame.Renderer, frame.Grid, warnings);
  for (const std::string& warning : warnings)
  {
    this->Notices.Report(warning, false);
  }
  frame.Lights = &this->Lights;
  frame.LitScene = this->Lights.GetCount() > 0;
  if (!frame.LitScene && !emission)
  {
    this->Notices.Warning(Gate::Unlit,
      "The scene has no light and no emissive prop: nothing to illuminate, rendering without "
      "GI.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void FramePlanner::Voxelized(const Frame& frame)
{
  this->Scan.Accept(frame.Plan.Voxels, frame.Config);
  this->History.VoxelsWritten();
}

void FramePlanner::Lit(const Frame& frame, bool valid, const std::string& note)
{
  if (valid)
  {
    this->Lights.MarkLit();
  }
  if (!note.empty())
  {
    this->Notices.Report(note, false);
  }
  this->History.Lit(frame.Plan.Lights, valid, frame.Config, frame.Grid);
}

void FramePlanner::Presented(const Frame& frame, bool traced, vtkMTimeType settingsTime)
{
  if (traced)
  {
    // What the image shows, read after VTK drew it (what VTK modified while drawing is no
    // change of the scene).
    this->History.Traced(
      *frame.Radiance, settingsTime, this->Scan.ImageKey(frame.Renderer, settingsTime, false));
  }
  else
  {
    this->History.NotTraced();
  }
  if (frame.Plan.Voxels.Run)
  {
    this->Scan.RefreshSignatures();
  }
  vtkTimeStamp now;
  now.Modified();
  this->Last = { frame.Renderer, now.GetMTime() };
}

void FramePlanner::Forget()
{
  this->Scan.Reset();
  this->History.Forget();
}

}
