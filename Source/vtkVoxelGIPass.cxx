#include "vtkVoxelGIPass.h"

#include "Frame.h"
#include "FramePlanner.h"
#include "Gate.h"
#include "ImageStages.h"
#include "PropKeys.h"
#include "Ranks.h"
#include "SourceLink.h"
#include "StageIds.h"
#include "VolumeReadback.h"
#include "VoxelMemory.h"
#include "VoxelStages.h"
#include "VoxelView.h"
#include "WindowFollower.h"

#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkVoxelGIPass);
vtkCxxSetObjectMacro(vtkVoxelGIPass, DelegatePass, vtkRenderPass);

vtkInformationKeyRestrictedMacro(vtkVoxelGIPass, EMISSION, DoubleVector, 3);
vtkInformationKeyMacro(vtkVoxelGIPass, DYNAMIC, Integer);

// The stages, wired to the results they read (see docs/architecture.md), the frame and its
// plan, and the units that decide whether GI runs.
struct vtkVoxelGIPass::Internals
{
  explicit Internals(vtkVoxelGIPass* pass)
    : Gate(pass)
    , Follower([pass](vtkOpenGLRenderWindow* w) { pass->ReleaseGraphicsResources(w); })
  {
  }
  voxelgi::Gate Gate;
  voxelgi::Ranks Processes;
  voxelgi::FramePlanner Planner{ Gate, Processes };
  voxelgi::VoxelStages Voxels;
  voxelgi::ImageStages Images;
  voxelgi::StageClock Clock;
  voxelgi::Frame Frame;
  voxelgi::VoxelMemory Memory;
  voxelgi::WindowFollower Follower; // the window whose context holds the resources
  voxelgi::SourceLink Link;          // whose voxels are shared with whom
};

vtkVoxelGIPass::vtkVoxelGIPass()
  : Internal(new Internals(this))
{
  vtkNew<vtkRenderStepsPass> steps;
  this->SetDelegatePass(steps);
}

vtkVoxelGIPass::~vtkVoxelGIPass()
{
  this->Internal->Follower.Follow(nullptr);
  this->SetDelegatePass(nullptr);
  this->SetVoxelSource(nullptr);
}

void vtkVoxelGIPass::SetVoxelSource(vtkVoxelGIPass* source)
{
  voxelgi::SourceLink& link = this->Internal->Link;
  voxelgi::SourceLink* to = source ? &source->Internal->Link : nullptr;
  if (const char* refusal = link.Refusal(to, source == this))
  {
    vtkErrorMacro(<< "SetVoxelSource: " << refusal << "; the voxel source is left unchanged.");
    return;
  }
  link.Move(this->VoxelSource ? &this->VoxelSource->Internal->Link : nullptr, to);
  vtkSetObjectBodyMacro(VoxelSource, vtkVoxelGIPass, source);
}

void vtkVoxelGIPass::SetPropEmission(vtkProp* prop, double r, double g, double b)
{
  const double rgb[3] = { r, g, b };
  if (prop && !voxelgi::SetEmissionKey(prop, rgb))
  {
    vtkGenericWarningMacro(<< "vtkVoxelGIPass::SetPropEmission: emission (" << r << ", " << g
                           << ", " << b
                           << ") must be finite and non-negative; the prop's emission is left "
                              "unchanged.");
  }
}

void vtkVoxelGIPass::SetPropDynamic(vtkProp* prop, bool dynamic)
{
  voxelgi::SetDynamicKey(prop, dynamic);
}

bool vtkVoxelGIPass::GetStageRan(int stage) const
{
  return this->Internal->Clock.Ran(stage);
}

bool vtkVoxelGIPass::GetSoftwareProfileActive() const
{
  return this->Internal->Gate.SoftwareProfileApplies(this->SoftwareProfile);
}

bool vtkVoxelGIPass::GetTraceReused() const
{
  return this->GetStageRan(STAGE_CONE_TRACE) && this->Internal->Images.Trace.GetReused();
}

double vtkVoxelGIPass::GetStageTime(int stage) const
{
  return this->Internal->Clock.Milliseconds(stage);
}

const char* vtkVoxelGIPass::GetStageName(int stage)
{
  return voxelgi::stage::Name(stage);
}

int vtkVoxelGIPass::GetGridResolution() const
{
  return this->TracedVoxels().Grid.Resolution;
}

void vtkVoxelGIPass::GetGridOrigin(double origin[3]) const
{
  const glm::dvec3 corner = this->TracedVoxels().Grid.Origin;
  std::copy(&corner.x, &corner.x + 3, origin);
}

double vtkVoxelGIPass::GetGridVoxelSize() const
{
  return this->TracedVoxels().Grid.VoxelSize;
}

bool vtkVoxelGIPass::GetUsedHardwareConservativeRaster() const
{
  return this->Internal->Voxels.Voxelize->GetHardwareConservative();
}

void vtkVoxelGIPass::Invalidate()
{
  this->Internal->Planner.Scan.Invalidate();
  this->Internal->Gate.Retry();
}

double vtkVoxelGIPass::GetRankTrafficBytes() const
{
  return static_cast<double>(this->Internal->Processes.GetBytes());
}

double vtkVoxelGIPass::GetRankTrafficMilliseconds() const
{
  return this->Internal->Processes.GetMilliseconds();
}

unsigned long long vtkVoxelGIPass::GetAllocatedBytes(int resource) const
{
  return this->Internal->Voxels.AllocatedBytes(resource);
}

unsigned long long vtkVoxelGIPass::GetRequiredVoxelMemoryBytes(bool emission)
{
  return voxelgi::VoxelMemoryNeed(emission, false,
    voxelgi::Snapshot(this, false, this->GetSoftwareProfileActive()),
    this->Internal->Planner.Lights.GetLights())
    .Total();
}

bool vtkVoxelGIPass::GetGIActive() const
{
  return this->GIActive && this->Internal->Follower.Served();
}

unsigned long long vtkVoxelGIPass::GetVoxelMemoryBytes() const
{
  return this->Internal->Voxels.MemoryBytes();
}

voxelgi::VoxelView vtkVoxelGIPass::TracedVoxels() const
{
  return this->VoxelSource ? this->VoxelSource->ViewVoxels() : this->ViewVoxels();
}

voxelgi::VoxelView vtkVoxelGIPass::ViewVoxels() const
{
  const Internals& in = *this->Internal;
  voxelgi::VoxelView view;
  view.Window = in.Follower.Get();
  view.Shares = this->VoxelSource != nullptr;
  view.Active = this->GIActive;
  view.Grid = in.Planner.Scan.GetGrid();
  view.AnySpecular = in.Planner.Scan.GetAnySpecular();
  view.Voxelization = in.Voxels.Voxelize;
  view.Lighting = &in.Voxels.Lighting;
  view.Mipmap = &in.Voxels.Mipmap;
  view.Lights = &in.Planner.Lights;
  view.Shadows = &in.Voxels.Shadows;
  view.Radiance = &in.Planner.History.GetRadiance();
  view.Presented = in.Planner.LastPresented();
  return view;
}

// The frame: its plan, then each stage the plan asks for. A stage that cannot run turns GI
// off for the frame (plan.GI), and VTK's image is presented instead.
void vtkVoxelGIPass::Render(const vtkRenderState* s)
{
  Internals& in = *this->Internal;
  this->NumberOfRenderedProps = 0;
  if (!this->Serve(s->GetRenderer()))
  {
    this->RenderDelegate(s);
    return;
  }
  voxelgi::FramePlan& plan = this->PlanFrame(s);
  plan.GI = plan.GI && this->Voxelize();
  plan.GI = plan.GI && this->Relight();
  plan.GI = plan.GI && this->Trace();
  this->Present();
  in.Clock.Resolve();
}

void vtkVoxelGIPass::RenderRanks(vtkRenderer* renderer)
{
  Internals& in = *this->Internal;
  in.Processes.Update();
  if (!in.Processes.Distributed() || this->VoxelSource || !this->DelegatePass ||
    !this->Serve(renderer))
  {
    return;
  }
  voxelgi::FramePlan& plan = this->PlanVoxels(renderer, nullptr);
  plan.GI = plan.GI && this->Voxelize();
  plan.RanAhead = true;
  in.Processes.Hold(plan.GI);
  // A rank whose Render() is skipped (nothing in view) still runs GI with the others.
  this->GIActive = plan.GI;
}

bool vtkVoxelGIPass::Serve(vtkRenderer* renderer)
{
  bool renewed = false;
  const bool serves = this->Internal->Gate.Serve(this, renderer, renewed);
  if (renewed)
  {
    this->Internal->Planner.Forget();
  }
  return serves;
}

voxelgi::FramePlan& vtkVoxelGIPass::PlanFrame(const vtkRenderState* s)
{
  Internals& in = *this->Internal;
  voxelgi::Frame& frame = in.Frame;
  bool ranAhead = false;
  if (in.Processes.Take(ranAhead))
  {
    frame.Plan.GI = ranAhead;
    frame.State = s;
  }
  else
  {
    this->PlanVoxels(s->GetRenderer(), s);
  }
  if (this->VoxelSource)
  {
    frame.Plan.GI = frame.Plan.GI && this->FollowSource();
  }
  else
  {
    frame.Plan.GI = frame.Plan.GI &&
      in.Planner.PlanLights(frame, this->Configuration().Emission, this->GetMTime());
  }
  frame.Plan.VoxelView =
    this->DebugView >= DEBUG_VIEW_VOXEL_ALBEDO && this->DebugView <= DEBUG_VIEW_VOXEL_RADIANCE;
  return frame.Plan;
}

voxelgi::FramePlan& vtkVoxelGIPass::PlanVoxels(vtkRenderer* renderer, const vtkRenderState* s)
{
  Internals& in = *this->Internal;
  voxelgi::Frame& frame = in.Frame;
  frame.Plan = voxelgi::FramePlan();
  in.Clock.Reset();
  in.Clock.SetTiming(this->TimeStages != 0);
  this->GIActive = false;
  frame.State = s;
  frame.Renderer = renderer;
  const bool admitted = in.Gate.Admit(
    this, this->DelegatePass, renderer, this->Enabled != 0, this->ConeShadows != 0);
  if (admitted)
  {
    in.Follower.Follow(vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow()));
    frame.Window = in.Follower.Get();
    frame.RenderStarts = in.Follower.RenderStarts();
    frame.Delegate = this->DelegatePass;
    frame.Processes = &in.Processes;
    frame.Clock = &in.Clock;
    in.Voxels.Wire(frame);
    renderer->GetTiledSizeAndOrigin(&frame.Width, &frame.Height, &frame.X, &frame.Y);
    frame.Config = voxelgi::Snapshot(this, in.Gate.HasConservativeRaster(),
      in.Gate.SoftwareProfile(this->SoftwareProfile, this->VoxelResolution));
  }
  frame.Plan.GI = admitted && in.Gate.ViewportFits(frame.Width, frame.Height);
  if (!this->VoxelSource)
  {
    frame.Plan.GI = in.Planner.PlanVoxels(frame, frame.Plan.GI);
  }
  return frame.Plan;
}

bool vtkVoxelGIPass::FollowSource()
{
  Internals& in = *this->Internal;
  // Voxels of the pass's own from before it shared the source's are not needed any more,
  // nor what its scans read.
  if (in.Planner.Scan.GetGrid().Resolution > 0)
  {
    this->ReleaseVoxelStages(in.Follower.Get());
  }
  in.Planner.Scan.Reset();
  return in.Planner.PlanSource(in.Frame, this->VoxelSource->ViewVoxels(), this->GetMTime());
}

bool vtkVoxelGIPass::Voxelize()
{
  Internals& in = *this->Internal;
  voxelgi::Frame& frame = in.Frame;
  const voxelgi::VoxelUpdate& update = frame.Plan.Voxels;
  const bool refused = in.Gate.Refused(this->Configuration());
  if (!update.Run || frame.Plan.RanAhead)
  {
    return !refused;
  }
  std::string error;
  const bool prepared = !refused &&
    in.Memory.Fits(update.Emission, update.Translucent, frame.Config,
      this->GetVoxelMemoryBytes(), error) &&
    in.Voxels.Voxelize->Prepare(frame, error);
  // Ranks voxelize together (every Run is collective when distributed).
  if (!in.Processes.All(prepared))
  {
    if (!refused)
    {
      this->Refuse(prepared
          ? "another rank could not prepare its voxel volumes (that rank says why)"
          : error);
    }
    in.Planner.Scan.Reset();
    return false;
  }
  in.Planner.Voxelized(frame);
  in.Voxels.GridBlock.Bind(frame.Grid);
  in.Voxels.Voxelize->Run(frame);
  return true;
}

bool vtkVoxelGIPass::Relight()
{
  Internals& in = *this->Internal;
  const voxelgi::Frame& frame = in.Frame;
  if (frame.Plan.Lights == voxelgi::LightWork::Current)
  {
    return true;
  }
  in.Planner.Lights.Bind();
  in.Voxels.GridBlock.Bind(frame.Grid);
  std::string error, note;
  const bool ok = in.Voxels.Relight(frame, error, note);
  in.Planner.Lit(frame, ok, note);
  if (!ok)
  {
    this->Refuse(error);
  }
  return ok;
}

bool vtkVoxelGIPass::Trace()
{
  Internals& in = *this->Internal;
  const voxelgi::Frame& frame = in.Frame;
  std::string error;
  // Nothing to trace when only the presentation changed (and no voxel view is shown).
  if ((frame.Plan.Trace == voxelgi::TraceWork::Present && !frame.Plan.VoxelView) ||
    in.Images.Run(frame, in.Planner.Lights, in.Voxels.GridBlock, error))
  {
    return true;
  }
  this->Refuse(error);
  return false;
}

void vtkVoxelGIPass::Present()
{
  Internals& in = *this->Internal;
  const voxelgi::Frame& frame = in.Frame;
  this->GIActive = frame.Plan.GI;
  // A voxel debug view shows the voxels over VTK's whole image.
  if (!frame.Plan.GI || frame.Plan.VoxelView)
  {
    this->RenderDelegate(frame.State);
  }
  if (frame.Plan.GI)
  {
    in.Images.Presenter.Run(frame);
    this->NumberOfRenderedProps += in.Images.Presenter.GetNumberOfRenderedProps();
  }
  in.Planner.Presented(frame, frame.Plan.GI && !frame.Plan.VoxelView, this->GetMTime());
}

void vtkVoxelGIPass::RenderDelegate(const vtkRenderState* s)
{
  if (this->DelegatePass)
  {
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
  }
}

voxelgi::Configuration vtkVoxelGIPass::Configuration()
{
  const Internals& in = *this->Internal;
  const voxelgi::Frame& frame = in.Frame;
  // Without a voxelization this frame, the emission of the voxels held.
  const bool emission =
    frame.Plan.Voxels.Run ? frame.Plan.Voxels.Emission : in.Voxels.Voxelize->HasEmission();
  return { this->GetMTime(), emission, frame.Width, frame.Height };
}

void vtkVoxelGIPass::Refuse(const std::string& error)
{
  Internals& in = *this->Internal;
  in.Gate.Refuse(this->Configuration(), error);
  this->ReleaseStages(in.Follower.Get());
  this->Internal->Planner.Forget();
}

bool vtkVoxelGIPass::GetFloatImage(int image, vtkFloatArray* pixels)
{
  Internals& in = *this->Internal;
  return in.Planner.History.HasTracedImage() &&
    voxelgi::ReadImage(in.Images.Compositor, in.Follower.Get(), image, pixels);
}

bool vtkVoxelGIPass::GetVoxelVolume(int volume, vtkImageData* image)
{
  return voxelgi::ReadVolume(this->TracedVoxels(), volume, image);
}

void vtkVoxelGIPass::ReleaseGraphicsResources(vtkWindow* w)
{
  Internals& in = *this->Internal;
  in.Follower.InContext(w, [this, w, &in] {
    this->ReleaseStages(w);
    in.Clock.ReleaseGraphicsResources();
  });
  in.Planner.Forget();
  this->GIActive = false; // what passes sharing the voxels ask
  in.Gate.ReleaseGraphicsResources();
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
}

void vtkVoxelGIPass::ReleaseVoxelStages(vtkWindow* w)
{
  Internals& in = *this->Internal;
  in.Voxels.ReleaseGraphicsResources(w);
  in.Memory.Forget();
  in.Planner.History.Forget();
}

void vtkVoxelGIPass::ReleaseStages(vtkWindow* w)
{
  Internals& in = *this->Internal;
  this->ReleaseVoxelStages(w);
  in.Voxels.GridBlock.ReleaseGraphicsResources(w);
  in.Planner.Lights.ReleaseGraphicsResources(w);
  in.Images.ReleaseGraphicsResources(w);
}

void vtkVoxelGIPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: " << static_cast<void*>(this->DelegatePass) << "\n";
  os << indent << "VoxelSource: " << static_cast<void*>(this->VoxelSource) << " (shared by "
     << this->Internal->Link.GetSharers() << " passes)\n";
  os << indent << "GIActive: " << this->GIActive << "\n";
  os << indent << "SoftwareProfileActive: " << this->GetSoftwareProfileActive() << "\n";
  const voxelgi::VoxelGrid grid = this->TracedVoxels().Grid;
  os << indent << "Grid: " << grid.Resolution << "^3 voxels of " << grid.VoxelSize << " from ("
     << grid.Origin.x << ", " << grid.Origin.y << ", " << grid.Origin.z << ")\n";
  os << indent << "VoxelMemoryBytes: " << this->GetVoxelMemoryBytes() << "\n";
  this->Internal->Clock.Print(os, indent);
}
