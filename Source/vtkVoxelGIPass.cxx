#include "vtkVoxelGIPass.h"

#include "Composite.h"
#include "ConeTrace.h"
#include "DebugView.h"
#include "Frame.h"
#include "GBufferPass.h"
#include "GLHelpers.h"
#include "LightBlock.h"
#include "LightVoxels.h"
#include "Present.h"
#include "Ranks.h"
#include "SceneScan.h"
#include "ShadowMaps.h"
#include "VoxelBounce.h"
#include "VoxelGridBlock.h"
#include "VolumeReadback.h"
#include "VoxelMipmap.h"
#include "VoxelizePass.h"
#include "vtkVoxelGISettings.h"

#include "vtkCameraPass.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSSAOPass.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkVoxelGIPass);
vtkCxxSetObjectMacro(vtkVoxelGIPass, DelegatePass, vtkRenderPass);
vtkInformationKeyRestrictedMacro(vtkVoxelGIPass, EMISSION, DoubleVector, 3);
vtkInformationKeyMacro(vtkVoxelGIPass, DYNAMIC, Integer);

namespace
{
constexpr int MinResolution = 16;
constexpr int MaxResolution = 512;
}

// The stages, wired to the results they read (see docs/architecture.md), and what the pass
// remembers between frames.
struct vtkVoxelGIPass::Internals
{
  voxelgi::SceneScan Scan;
  vtkNew<voxelgi::VoxelizePass> Voxelize;
  voxelgi::VoxelGridBlock GridBlock;
  voxelgi::LightBlock Lights;
  voxelgi::ShadowMaps Shadows;
  voxelgi::LightVoxels Lighting{ *Voxelize, Shadows };
  voxelgi::VoxelMipmap Mipmap{ Lighting };
  voxelgi::VoxelBounce Bounce{ *Voxelize, Lighting, Mipmap };
  vtkNew<voxelgi::GBufferPass> GBuffer;
  voxelgi::ConeTrace Trace{ *GBuffer };
  voxelgi::Composite Compositor{ *GBuffer, Trace };
  voxelgi::DebugView Debug;
  voxelgi::Present Presenter;
  voxelgi::StageClock Clock;
  voxelgi::Frame Frame;
  voxelgi::Ranks Processes;
  bool WarnedRanks = false;
  // RenderRanks' results, which the next Render() takes: whether GI runs, and whether the
  // voxels changed since a Render() last took them (a rank may miss frames).
  bool RanksDone = false;
  bool RanksActive = false;
  bool RanksVoxelsChanged = false;

  bool Traced = false;
  vtkMTimeType TracedSettings = 0; // the settings' time at the last trace
  // Counts the frames that rewrote the voxels or their light in a way a trace cannot reuse;
  // a pass sharing these voxels compares it with the count it last traced.
  unsigned long long RadianceGeneration = 0;
  unsigned long long TracedGeneration = 0;
  bool WarnedSource = false;
  bool WarnedAliasing = false;
  bool WarnedUnlit = false;
  bool WarnedNoDelegate = false;
  vtkWeakPointer<vtkOpenGLRenderWindow> Window; // the window whose context holds the resources
  vtkWeakPointer<vtkRenderer> Renderer; // the renderer the voxels and images belong to
  bool WarnedShared = false;
  bool WarnedCombination = false;
  // The configuration whose stages could not be prepared (Refuse): settings' time, the
  // scene's emission and the viewport. GI stays off, silently, while the frame matches it.
  struct Configuration
  {
    vtkMTimeType Settings = 0;
    bool Emission = false;
    int Width = 0;
    int Height = 0;
    bool operator==(const Configuration& o) const
    {
      return Settings == o.Settings && Emission == o.Emission && Width == o.Width &&
        Height == o.Height;
    }
  };
  Configuration Current;
  Configuration RefusedConfiguration;
  bool HasRefused = false;
  std::size_t FittingBytes = 0; // the last voxel memory need found to fit
  unsigned long WindowObserver = 0;
  bool ContextChecked = false;
  bool ContextOk = false;
  vtkWeakPointer<vtkRenderWindow> CheckedWindow; // the window whose context was checked
  bool HasConservativeRaster = false;
  int RefusedSize[2] = { 0, 0 }; // the viewport size last refused as too large (said once)
};

//------------------------------------------------------------------------------
vtkVoxelGIPass::vtkVoxelGIPass()
  : Internal(new Internals)
{
  vtkNew<vtkRenderStepsPass> steps;
  this->SetDelegatePass(steps);
  // Defaults come from the settings table.
  for (int i = 0; i < vtkVoxelGISettings::GetNumberOfSettings(); ++i)
  {
    vtkVoxelGISettings::SetValue(
      this, vtkVoxelGISettings::GetName(i), vtkVoxelGISettings::GetDefault(i));
  }
}

vtkVoxelGIPass::~vtkVoxelGIPass()
{
  this->WatchWindow(nullptr);
  this->SetDelegatePass(nullptr);
  this->SetVoxelSource(nullptr);
}

//------------------------------------------------------------------------------
void vtkVoxelGIPass::WatchWindow(vtkOpenGLRenderWindow* window)
{
  Internals& in = *this->Internal;
  if (window == in.Window.GetPointer())
  {
    return;
  }
  // GL objects are freed with their own context current: when the pass leaves a window, and
  // when the window goes away (its DeleteEvent comes while its context still exists).
  if (in.Window)
  {
    in.Window->RemoveObserver(in.WindowObserver);
    in.Window->PushContext();
    this->ReleaseGraphicsResources(in.Window);
    in.Window->PopContext();
  }
  in.Window = window;
  in.WindowObserver = window
    ? window->AddObserver(vtkCommand::DeleteEvent, this, &vtkVoxelGIPass::WindowDeleted)
    : 0;
}

void vtkVoxelGIPass::WindowDeleted()
{
  this->WatchWindow(nullptr);
}

//------------------------------------------------------------------------------
void vtkVoxelGIPass::SetVoxelSource(vtkVoxelGIPass* source)
{
  // A source owns its voxels: no chains, hence no cycles of references.
  if (source && (source == this || source->VoxelSource))
  {
    vtkErrorMacro(<< "SetVoxelSource: "
                  << (source == this ? "a pass cannot share its own voxels"
                                     : "that pass shares another pass's voxels itself")
                  << "; the voxel source is left unchanged.");
    return;
  }
  vtkSetObjectBodyMacro(VoxelSource, vtkVoxelGIPass, source);
}

//------------------------------------------------------------------------------
void vtkVoxelGIPass::SetVoxelResolution(int resolution)
{
  const int clamped = voxelgi::ClampResolution(resolution, MinResolution, MaxResolution);
  if (clamped != resolution)
  {
    std::ostringstream message;
    message << "VoxelResolution " << resolution << " is not a power of two in [16, 512]";
    if (resolution > MaxResolution)
    {
      message << " (it would need "
              << voxelgi::VoxelizePass::RequiredBytes(resolution, false) / (1024 * 1024)
              << " MiB of voxel memory)";
    }
    vtkWarningMacro(<< message.str() << "; using " << clamped << ".");
  }
  if (clamped != this->VoxelResolution)
  {
    this->VoxelResolution = clamped;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
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
  if (prop)
  {
    voxelgi::EnsurePropertyKeys(prop)->Set(DYNAMIC(), dynamic ? 1 : 0);
  }
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::GetStageRan(int stage) const
{
  return stage >= 0 && stage < NUMBER_OF_STAGES && this->Internal->Clock.Ran(stage);
}

bool vtkVoxelGIPass::GetTraceReused() const
{
  return this->GetStageRan(STAGE_CONE_TRACE) && this->Internal->Trace.GetReused();
}

double vtkVoxelGIPass::GetStageTime(int stage) const
{
  return (stage >= 0 && stage < NUMBER_OF_STAGES) ? this->Internal->Clock.Milliseconds(stage)
                                                  : 0.0;
}

const char* vtkVoxelGIPass::GetStageName(int stage)
{
  static const char* names[NUMBER_OF_STAGES] = { "Scan", "Clear", "VoxelizeStatic",
    "VoxelizeDynamic", "Resolve", "ShadowMaps", "LightVoxels", "Mipmap", "Bounce", "GBuffer",
    "ConeTrace", "Present", "DebugView" };
  return (stage >= 0 && stage < NUMBER_OF_STAGES) ? names[stage] : "Unknown";
}

const vtkVoxelGIPass* vtkVoxelGIPass::VoxelOwner() const
{
  return this->VoxelSource ? this->VoxelSource : this;
}

int vtkVoxelGIPass::GetGridResolution() const
{
  return this->VoxelOwner()->Internal->Scan.GetGrid().Resolution;
}

void vtkVoxelGIPass::GetGridOrigin(double origin[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    origin[a] = this->VoxelOwner()->Internal->Scan.GetGrid().Origin[a];
  }
}

double vtkVoxelGIPass::GetGridVoxelSize() const
{
  return this->VoxelOwner()->Internal->Scan.GetGrid().VoxelSize;
}

bool vtkVoxelGIPass::GetUsedHardwareConservativeRaster() const
{
  return this->Internal->Voxelize->GetHardwareConservative();
}

void vtkVoxelGIPass::Invalidate()
{
  this->Internal->Scan.Invalidate();
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
  const Internals& in = *this->Internal;
  switch (resource)
  {
    case RESOURCE_VOXELIZATION:
      return in.Voxelize->MemoryBytes() - in.Voxelize->EmissionBytes();
    case RESOURCE_EMISSION:
      return in.Voxelize->EmissionBytes();
    case RESOURCE_RADIANCE:
      return in.Lighting.GetRadiance().Bytes();
    case RESOURCE_DIRECT:
      return in.Lighting.GetDirect().Bytes();
    case RESOURCE_DIRECTIONAL:
      return in.Mipmap.MemoryBytes();
    case RESOURCE_SHADOW_MAPS:
      return in.Shadows.Maps.Bytes();
    default:
      return 0;
  }
}

namespace
{
/// What the voxel volumes of `settings` need, per stage.
struct VoxelMemory
{
  std::size_t Voxelization, Radiance, Mipmaps;
  VoxelMemory(bool emission, const voxelgi::Settings& settings)
    : Voxelization(voxelgi::VoxelizePass::RequiredBytes(settings.VoxelResolution, emission))
    , Radiance(voxelgi::LightVoxels::RequiredBytes(settings.VoxelResolution, settings))
    , Mipmaps(voxelgi::VoxelMipmap::RequiredBytes(settings.VoxelResolution, settings))
  {
  }
  std::size_t Total() const { return this->Voxelization + this->Radiance + this->Mipmaps; }
};
}

unsigned long long vtkVoxelGIPass::GetRequiredVoxelMemoryBytes(bool emission)
{
  return VoxelMemory(emission, voxelgi::Snapshot(this, false)).Total();
}

unsigned long long vtkVoxelGIPass::GetVoxelMemoryBytes() const
{
  const Internals& in = *this->Internal;
  return in.Voxelize->MemoryBytes() + in.Lighting.MemoryBytes() + in.Mipmap.MemoryBytes() +
    in.Shadows.Maps.Bytes();
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::CheckContext(vtkRenderWindow* renWin)
{
  Internals& in = *this->Internal;
  // The window is only followed once GI runs in it: a refused context is checked once too.
  if (in.ContextChecked && renWin == in.CheckedWindow.GetPointer())
  {
    return in.ContextOk;
  }
  int major = 0, minor = 0;
  voxelgi::ContextVersion(major, minor);
  in.ContextChecked = true;
  in.CheckedWindow = renWin;
  in.ContextOk = major > 4 || (major == 4 && minor >= 3);
  in.HasConservativeRaster = voxelgi::HasExtension("GL_NV_conservative_raster");
  if (!in.ContextOk)
  {
    vtkErrorMacro(<< "Voxel GI needs OpenGL 4.3 (compute shaders, image load/store, shader "
                     "storage buffers) but this context provides "
                  << major << "." << minor << ". Rendering without GI.");
  }
  return in.ContextOk;
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::BeginFrame(vtkRenderer* renderer, const vtkRenderState* s)
{
  Internals& in = *this->Internal;
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  // Hardware picking renders through the pass too: it must see VTK's plain render steps.
  if (!(this->Enabled && renWin && !renderer->GetSelector() && this->PassesCombine(renderer) &&
        this->CheckContext(renWin)))
  {
    return false;
  }
  this->WatchWindow(renWin);
  voxelgi::Frame& frame = in.Frame;
  frame.Renderer = renderer;
  frame.Window = in.Window;
  frame.State = s;
  frame.Delegate = this->DelegatePass;
  frame.Processes = &in.Processes;
  frame.Clock = &in.Clock;
  frame.Grid = in.Scan.GetGrid();
  frame.Actors = &in.Scan.GetRecords();
  frame.Voxelization = in.Voxelize;
  frame.Lighting = &in.Lighting;
  frame.Mipmap = &in.Mipmap;
  frame.Shadows = &in.Shadows;
  frame.Renderer->GetTiledSizeAndOrigin(&frame.Width, &frame.Height, &frame.X, &frame.Y);
  frame.Config = voxelgi::Snapshot(this, in.HasConservativeRaster);
  return this->ViewportFits();
}

bool vtkVoxelGIPass::UpdateShared(bool runs, bool& voxelsChanged)
{
  voxelsChanged = false;
  return this->RanksAgree(runs) && this->UpdateVoxels(voxelsChanged);
}

void vtkVoxelGIPass::RenderRanks(vtkRenderer* renderer)
{
  Internals& in = *this->Internal;
  in.Processes.Update();
  if (!in.Processes.Distributed() || this->VoxelSource || !this->DelegatePass ||
    !this->ServeRenderer(renderer))
  {
    return;
  }
  in.Clock.Reset();
  in.Clock.SetTiming(this->TimeStages != 0);
  bool changed = false;
  in.RanksActive = this->UpdateShared(this->BeginFrame(renderer, nullptr), changed);
  in.RanksVoxelsChanged = in.RanksVoxelsChanged || changed;
  in.RanksDone = true;
  // A rank whose Render() is skipped (nothing in view) still runs GI with the others.
  this->GIActive = in.RanksActive;
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::ViewportFits()
{
  Internals& in = *this->Internal;
  // Every image of the frame has the viewport's size: beyond GL's limits none can be made.
  const std::string tooLarge =
    voxelgi::ImageSizeError("the viewport", in.Frame.Width, in.Frame.Height);
  if (tooLarge.empty())
  {
    in.RefusedSize[0] = in.RefusedSize[1] = 0;
    return true;
  }
  if (in.RefusedSize[0] != in.Frame.Width || in.RefusedSize[1] != in.Frame.Height)
  {
    vtkErrorMacro(<< "Voxel GI disabled for this frame: " << tooLarge
                  << "; rendering without GI.");
    in.RefusedSize[0] = in.Frame.Width;
    in.RefusedSize[1] = in.Frame.Height;
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::MemoryFits(bool emission)
{
  Internals& in = *this->Internal;
  const VoxelMemory memory(emission, in.Frame.Config);
  const std::size_t need = memory.Total();
  if (need == in.FittingBytes)
  {
    return true;
  }
  std::string source;
  const long long available = voxelgi::AvailableMemory(source);
  // What the pass holds now is freed before the new volumes are made.
  const unsigned long long held = this->GetVoxelMemoryBytes();
  if (available >= 0 && need > static_cast<unsigned long long>(available) + held)
  {
    const auto mib = [](unsigned long long bytes) { return bytes / (1024 * 1024); };
    std::ostringstream msg;
    msg << "VoxelResolution " << in.Frame.Config.VoxelResolution << " needs " << mib(need)
        << " MiB for its voxel volumes (voxelization " << mib(memory.Voxelization)
        << ", radiance " << mib(memory.Radiance) << ", mipmaps " << mib(memory.Mipmaps)
        << " MiB) but only " << mib(available + held) << " MiB are free (" << source
        << "; a lower VoxelResolution needs an eighth per halving)";
    this->Refuse(msg.str());
    return false;
  }
  in.FittingBytes = need;
  return true;
}

void vtkVoxelGIPass::Refuse(const std::string& error)
{
  Internals& in = *this->Internal;
  if (!in.HasRefused || !(in.RefusedConfiguration == in.Current))
  {
    vtkErrorMacro(<< "Voxel GI disabled: " << error
                  << ". Rendering without GI until a setting changes.");
  }
  in.HasRefused = true;
  in.RefusedConfiguration = in.Current;
  in.FittingBytes = 0;
  this->ReleaseStages(in.Window);
  in.Traced = false;
  in.Scan.Reset();
}

bool vtkVoxelGIPass::Refused() const
{
  const Internals& in = *this->Internal;
  return in.HasRefused && in.RefusedConfiguration == in.Current;
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::ServeRenderer(vtkRenderer* renderer)
{
  Internals& in = *this->Internal;
  // One pass keeps the voxels and images of one renderer. A second renderer of the same
  // window that shares it (viewports, layers) gets VTK's image: rebuilding for each in turn
  // would cost a full voxelization per renderer per frame. The first renderer's results are
  // left as they are. (Renderers of two windows take turns, each frame exact: a window's
  // frames are whole.)
  vtkRenderer* owner = in.Renderer;
  if (owner && owner != renderer && owner->GetPass() == this &&
    owner->GetRenderWindow() == renderer->GetRenderWindow())
  {
    if (!in.WarnedShared)
    {
      vtkErrorMacro(<< "This pass is set on two renderers of one window; it renders GI for the "
                       "first only and VTK's image for the other. Give each renderer a pass of "
                       "its own (SetVoxelSource lets them share one voxel grid).");
      in.WarnedShared = true;
    }
    return false;
  }
  if (owner != renderer)
  {
    in.Renderer = renderer;
    in.Scan.Reset();
    in.Traced = false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::PassesCombine(vtkRenderer* renderer)
{
  Internals& in = *this->Internal;
  // vtkSSAOPass draws its delegate into a framebuffer of its own whose extra attachments
  // (positions, normals) only VTK's opaque step writes, and blends its result into the
  // framebuffer bound outside it: neither the G-buffer nor the present can sit on either side.
  std::string reason;
  if (vtkSSAOPass::SafeDownCast(this->DelegatePass))
  {
    reason = "its delegate is a vtkSSAOPass";
  }
  for (vtkRenderPass* pass = renderer->GetPass(); pass && pass != this && reason.empty();)
  {
    if (vtkSSAOPass::SafeDownCast(pass))
    {
      reason = "it is the delegate of a vtkSSAOPass";
    }
    else if (auto* processing = vtkImageProcessingPass::SafeDownCast(pass))
    {
      pass = processing->GetDelegatePass();
    }
    else if (auto* camera = vtkCameraPass::SafeDownCast(pass))
    {
      pass = camera->GetDelegatePass();
    }
    else
    {
      pass = nullptr;
    }
  }
  if (reason.empty())
  {
    in.WarnedCombination = false;
    return true;
  }
  if (!in.WarnedCombination)
  {
    vtkErrorMacro(<< "Voxel GI cannot run here: " << reason
                  << " (screen-space AO needs VTK's own opaque framebuffer). Rendering "
                     "without GI; the AmbientOcclusion setting is GI's own occlusion.");
    in.WarnedCombination = true;
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkVoxelGIPass::Render(const vtkRenderState* s)
{
  Internals& in = *this->Internal;
  this->NumberOfRenderedProps = 0;
  if (!this->ServeRenderer(s->GetRenderer()))
  {
    if (this->DelegatePass)
    {
      this->RenderDelegate(s);
    }
    return;
  }
  if (!in.RanksDone)
  {
    in.Clock.Reset();
    in.Clock.SetTiming(this->TimeStages != 0);
  }
  this->GIActive = false;
  const bool traced = in.Traced;
  in.Traced = false;
  vtkRenderer* renderer = s->GetRenderer();
  bool voxelsChanged = false;
  bool radianceChanged = false;
  if (!this->DelegatePass)
  {
    if (!in.WarnedNoDelegate)
    {
      vtkErrorMacro(<< "No delegate pass: nothing renders VTK's image, so neither VTK's image "
                       "nor GI is drawn. Set one (e.g. a vtkRenderStepsPass).");
      in.WarnedNoDelegate = true;
    }
    return;
  }
  in.WarnedNoDelegate = false;
  const bool runs = this->BeginFrame(renderer, s);
  if (!this->VoxelSource)
  {
    bool active = false;
    if (in.RanksDone)
    {
      active = runs && in.RanksActive;
      voxelsChanged = in.RanksVoxelsChanged;
      in.RanksDone = in.RanksVoxelsChanged = false;
    }
    else
    {
      active = this->UpdateShared(runs, voxelsChanged);
    }
    this->GIActive = active && this->UpdateRadiance(voxelsChanged, radianceChanged);
    in.RadianceGeneration += (voxelsChanged || radianceChanged) ? 1 : 0;
  }
  else if (runs)
  {
    this->GIActive = this->FollowSource(radianceChanged);
  }

  const bool voxelView = this->DebugView >= DEBUG_VIEW_VOXEL_ALBEDO &&
    this->DebugView <= DEBUG_VIEW_VOXEL_RADIANCE;
  if (!this->GIActive || voxelView)
  {
    in.Scan.ForgetFrame();
    this->RenderDelegate(s);
  }
  else
  {
    const bool unchanged = in.Scan.Unchanged(renderer, this->GetMTime());
    in.Frame.CameraOnly = traced && !voxelsChanged && !radianceChanged &&
      this->GetMTime() == in.TracedSettings;
    this->RenderGI(in.Frame.CameraOnly && unchanged);
    in.Scan.RememberFrame(renderer, this->GetMTime());
  }
  if (this->GIActive && voxelView)
  {
    this->RenderVoxelView();
  }
  if (voxelsChanged)
  {
    in.Scan.RefreshSignatures();
  }
  in.Clock.Resolve(NUMBER_OF_STAGES);
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::RanksAgree(bool runs)
{
  Internals& in = *this->Internal;
  in.Processes.Update();
  if (!in.Processes.Distributed())
  {
    return runs;
  }
  // Every rank voxelizes its piece into one grid: either all run GI, or none.
  in.Processes.ResetTraffic();
  const bool all = in.Processes.All(runs);
  if (runs && !all && !in.WarnedRanks)
  {
    vtkErrorMacro(<< "Voxel GI is off on every rank: another of the "
                  << in.Processes.Count()
                  << " ranks cannot run it (that rank says why). Rendering without GI.");
  }
  in.WarnedRanks = runs && !all;
  return all;
}

//------------------------------------------------------------------------------
void vtkVoxelGIPass::RenderDelegate(const vtkRenderState* s)
{
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::UpdateVoxels(bool& changed)
{
  Internals& in = *this->Internal;
  voxelgi::Frame& frame = in.Frame;
  voxelgi::ScanMessages messages;
  const bool ok = in.Scan.Scan(frame.Renderer, frame.Config, in.Processes, frame.Voxels, messages);
  in.Clock.SetCpuTime(STAGE_SCAN, in.Scan.GetMilliseconds());
  for (const std::string& warning : messages.Warnings)
  {
    vtkWarningMacro(<< warning);
  }
  if (!messages.Error.empty())
  {
    vtkErrorMacro(<< messages.Error);
  }
  frame.AnySpecular = in.Scan.GetAnySpecular();
  this->NoticeAliasing();
  changed = false;
  if (!ok)
  {
    return false;
  }
  const bool emission = frame.Voxels.Run ? frame.Voxels.Emission : in.Voxelize->HasEmission();
  in.Current = { this->GetMTime(), emission, frame.Width, frame.Height };
  const bool refused = this->Refused();
  if (!frame.Voxels.Run && !refused)
  {
    return true;
  }
  std::string error;
  bool prepared = !refused && this->MemoryFits(emission);
  if (prepared && !in.Voxelize->Prepare(frame, error))
  {
    this->Refuse(error);
    prepared = false;
  }
  // Ranks voxelize together (every Run is collective when distributed).
  if (frame.Voxels.Run && in.Processes.Distributed())
  {
    const bool all = in.Processes.All(prepared);
    if (prepared && !all)
    {
      this->Refuse("another rank could not prepare its voxel volumes (that rank says why)");
    }
    prepared = all;
  }
  if (!prepared)
  {
    in.Scan.Reset();
    return false;
  }
  in.Scan.Accept(frame.Voxels, frame.Config);
  frame.Grid = in.Scan.GetGrid();
  in.GridBlock.Bind(frame.Grid);
  in.Voxelize->Run(frame);
  changed = true;
  return true;
}

void vtkVoxelGIPass::NoticeAliasing()
{
  Internals& in = *this->Internal;
  const int windowSamples = in.Frame.Window->GetMultiSamples();
  if (in.WarnedAliasing || windowSamples < 2 || this->GBufferSamples > 1 ||
    !in.Scan.GetAnyLines())
  {
    return;
  }
  vtkWarningMacro(<< "The window is multisampled (" << windowSamples
                  << " samples) but the GI G-buffer has one sample (GBufferSamples "
                  << this->GBufferSamples
                  << "): lines, edges and 3D text that VTK anti-aliases are drawn aliased. "
                     "SetGBufferSamples("
                  << windowSamples
                  << ") keeps them anti-aliased, at the cost of drawing the G-buffer with as "
                     "many samples.");
  in.WarnedAliasing = true;
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::UpdateRadiance(bool voxelsChanged, bool& changed)
{
  Internals& in = *this->Internal;
  voxelgi::Frame& frame = in.Frame;
  bool lightsChanged = false;
  changed = false;
  if (!this->GatherLights(in.Voxelize->HasEmission(), lightsChanged))
  {
    in.Lighting.SetCurrent(frame, false);
    return false;
  }
  in.GridBlock.Bind(frame.Grid);
  // Camera-following lights turn with every camera move: their voxel light is kept until
  // they have turned by more than CameraLightTurn (VTK's own direct light stays exact).
  const double turn = lightsChanged ? in.Lights.CameraTurnSinceLit() : 0.0;
  const bool relight = voxelsChanged || (lightsChanged && !(turn <= frame.Config.CameraLightTurn));
  if (in.Lighting.IsCurrent(frame, relight))
  {
    return true;
  }
  // Only camera lights turned, and the last solution is for these voxels and settings: the
  // relight continues from it, and the frame counts as a camera move for the trace.
  const bool follow = !voxelsChanged && std::isfinite(turn) && in.Lighting.IsCurrent(frame, false);
  changed = !follow;
  const bool valid = this->LightAndBounce(follow);
  in.Lighting.SetCurrent(frame, valid);
  if (valid)
  {
    in.Lights.MarkLit();
  }
  return valid;
}

bool vtkVoxelGIPass::GatherLights(bool emission, bool& changed)
{
  Internals& in = *this->Internal;
  voxelgi::Frame& frame = in.Frame;
  std::vector<std::string> warnings;
  changed = in.Lights.Gather(frame.Renderer, frame.Grid, warnings);
  for (const std::string& warning : warnings)
  {
    vtkWarningMacro(<< warning);
  }
  frame.LitScene = in.Lights.GetCount() > 0;
  if (!frame.LitScene && !emission)
  {
    if (!in.WarnedUnlit)
    {
      vtkWarningMacro(<< "The scene has no light and no emissive prop: nothing to illuminate, "
                         "rendering without GI.");
      in.WarnedUnlit = true;
    }
    return false;
  }
  in.Lights.Bind();
  return true;
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::FollowSource(bool& changed)
{
  Internals& in = *this->Internal;
  voxelgi::Frame& frame = in.Frame;
  changed = false;
  const vtkVoxelGIPass* source = this->VoxelSource;
  const Internals& shared = *source->Internal;
  const char* error = source->VoxelSource
    ? "its VoxelSource shares another pass's voxels itself"
    : (shared.Window && shared.Window != in.Window
          ? "its VoxelSource renders into another window (voxels stay in their window's context)"
          : nullptr);
  if (error)
  {
    if (!in.WarnedSource)
    {
      vtkErrorMacro(<< "Voxel GI cannot run: " << error << ". Rendering without GI.");
      in.WarnedSource = true;
    }
    return false;
  }
  in.WarnedSource = false;
  // Voxels of the pass's own from before it shared the source's are not needed any more.
  if (in.Scan.GetGrid().Resolution > 0)
  {
    this->ReleaseVoxelStages(in.Window);
    in.Scan.Reset();
  }
  // The source says why when it has no GI; before its first frame there is nothing to trace.
  if (!source->GIActive || !shared.Window)
  {
    return false;
  }
  frame.Grid = shared.Scan.GetGrid();
  frame.AnySpecular = shared.Scan.GetAnySpecular();
  frame.Voxelization = shared.Voxelize;
  frame.Lighting = &shared.Lighting;
  frame.Mipmap = &shared.Mipmap;
  bool lightsChanged = false;
  if (!this->GatherLights(shared.Voxelize->HasEmission(), lightsChanged))
  {
    return false;
  }
  in.GridBlock.Bind(frame.Grid);
  // The source's shadow maps are of its lights: they serve this renderer's pixels when it
  // has the same lights (viewports on one scene), else its shadows are traced.
  frame.Shadows = in.Lights.GetLights() == shared.Lights.GetLights() ? &shared.Shadows : nullptr;
  // This renderer's lights shade VTK's image and aim the shadow cones; the voxels are lit by
  // the source's. Camera lights turning with this camera make a camera move.
  changed = shared.RadianceGeneration != in.TracedGeneration ||
    (lightsChanged && !std::isfinite(in.Lights.CameraTurnSinceLit()));
  in.Lights.MarkLit();
  in.TracedGeneration = shared.RadianceGeneration;
  return true;
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::LightAndBounce(bool follow)
{
  Internals& in = *this->Internal;
  const voxelgi::Frame& frame = in.Frame;
  std::string error;
  bool ok = true;
  // A rank's maps would see its own piece only; the raymarch sees the merged voxels.
  if (frame.Config.LightOcclusion == LIGHT_OCCLUSION_SHADOW_MAPS && !in.Processes.Distributed())
  {
    ok = in.Shadows.Prepare(frame, in.Lights, error);
    if (ok)
    {
      in.Shadows.Run(frame, in.Lights);
    }
  }
  else
  {
    in.Shadows.ReleaseGraphicsResources(in.Window);
  }
  ok = ok && in.Lighting.Prepare(frame, error) && in.Mipmap.Prepare(frame, error) &&
    (frame.Config.Bounces == 0 || in.Bounce.Prepare(frame, error));
  if (!ok)
  {
    this->Refuse(error);
    return false;
  }
  // After a camera light's turn the new direct light plus the last bounces' indirect light
  // is close to the converged radiance: one bounce from it stands for the whole chain.
  const bool continues = follow && frame.Config.Bounces > 0;
  in.Lighting.Run(frame, continues);
  in.Mipmap.Run(frame);
  if (frame.Config.Bounces > 0)
  {
    in.Bounce.Run(frame, continues ? 1 : frame.Config.Bounces);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkVoxelGIPass::RenderGI(bool reuse)
{
  Internals& in = *this->Internal;
  const voxelgi::Frame& frame = in.Frame;
  if (frame.Width <= 0 || frame.Height <= 0)
  {
    return;
  }
  if (!reuse && !this->TraceFrame())
  {
    this->GIActive = false;
    this->RenderDelegate(frame.State);
    return;
  }
  in.Traced = true;

  {
    // VTK's remaining steps are left out of the stage's time: plain VTK renders them too.
    voxelgi::ScopedStage stage(in.Clock, STAGE_PRESENT);
    in.Presenter.Run(frame, in.Compositor.GetDisplay(), in.GBuffer->GetDepth());
  }
  this->NumberOfRenderedProps += in.Presenter.RenderRemainingSteps(frame);
}

void vtkVoxelGIPass::RenderVoxelView()
{
  Internals& in = *this->Internal;
  // Timed with its Present.
  voxelgi::ScopedStage stage(in.Clock, STAGE_DEBUG_VIEW);
  std::string error;
  if (!in.Debug.Prepare(in.Frame, error))
  {
    vtkErrorMacro(<< "Voxel GI could not show the debug view: " << error << ".");
    return;
  }
  in.GridBlock.Bind(in.Frame.Grid);
  in.Debug.Run(in.Frame);
  in.Presenter.Run(in.Frame, in.Debug.GetImage(), nullptr);
}

bool vtkVoxelGIPass::TraceFrame()
{
  Internals& in = *this->Internal;
  const voxelgi::Frame& frame = in.Frame;
  std::string error;
  if (!in.GBuffer->Prepare(frame, error) || !in.Trace.Prepare(frame, error) ||
    !in.Compositor.Prepare(frame, error))
  {
    this->Refuse(error);
    return false;
  }
  in.GBuffer->Run(frame);
  this->NumberOfRenderedProps += in.GBuffer->GetNumberOfRenderedProps();
  // VTK's raster work came in between: bind the blocks again before the dispatches.
  in.Lights.Bind();
  in.GridBlock.Bind(frame.Grid);
  in.Trace.Run(frame);
  in.Compositor.Run(frame);
  in.TracedSettings = this->GetMTime();
  return true;
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::GetFloatImage(int image, vtkFloatArray* pixels)
{
  Internals& in = *this->Internal;
  std::vector<float> rgba;
  int w = 0, h = 0;
  if (!pixels || !in.Window || !in.Traced || !in.Compositor.Read(in.Window, image, rgba, w, h))
  {
    return false;
  }
  pixels->SetNumberOfComponents(4);
  pixels->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  std::copy(rgba.begin(), rgba.end(), pixels->GetPointer(0));
  return true;
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::GetVoxelVolume(int volume, vtkImageData* image)
{
  if (this->VoxelSource)
  {
    return this->VoxelSource->GetVoxelVolume(volume, image);
  }
  Internals& in = *this->Internal;
  const voxelgi::VoxelizePass& voxels = *in.Voxelize;
  const int res = voxels.GetResolution();
  if (!image || !in.Window || res <= 0 || (volume == VOLUME_EMISSION && !voxels.HasEmission()) ||
    (volume == VOLUME_RADIANCE && !in.Lighting.GetRadiance().IsAllocated()))
  {
    return false;
  }
  in.Window->MakeCurrent();
  return voxelgi::ReadVolume(voxels, in.Lighting.GetRadiance(), in.Scan.GetGrid(), volume, image);
}

//------------------------------------------------------------------------------
void vtkVoxelGIPass::ReleaseGraphicsResources(vtkWindow* w)
{
  Internals& in = *this->Internal;
  this->ReleaseStages(w);
  in.Clock.ReleaseGraphicsResources();
  in.Traced = false;
  in.Scan.Reset();
  in.ContextChecked = false;
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
}

void vtkVoxelGIPass::ReleaseVoxelStages(vtkWindow* w)
{
  Internals& in = *this->Internal;
  in.Voxelize->ReleaseGraphicsResources(w);
  in.Shadows.ReleaseGraphicsResources(w);
  in.Lighting.ReleaseGraphicsResources(w);
  in.Mipmap.ReleaseGraphicsResources(w);
  in.Bounce.ReleaseGraphicsResources(w);
  in.FittingBytes = 0;
}

void vtkVoxelGIPass::ReleaseStages(vtkWindow* w)
{
  Internals& in = *this->Internal;
  this->ReleaseVoxelStages(w);
  in.GridBlock.ReleaseGraphicsResources(w);
  in.Lights.ReleaseGraphicsResources(w);
  in.GBuffer->ReleaseGraphicsResources(w);
  in.Trace.ReleaseGraphicsResources(w);
  in.Compositor.ReleaseGraphicsResources(w);
  in.Debug.ReleaseGraphicsResources(w);
  in.Presenter.ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
void vtkVoxelGIPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: ";
  if (this->DelegatePass)
  {
    this->DelegatePass->PrintSelf(os, indent.GetNextIndent());
  }
  else
  {
    os << "(none)\n";
  }
  // Every setting of the table, so that none can be forgotten here.
  for (int i = 0; i < vtkVoxelGISettings::GetNumberOfSettings(); ++i)
  {
    const char* name = vtkVoxelGISettings::GetName(i);
    os << indent << name << ": " << vtkVoxelGISettings::GetValue(this, name) << "\n";
  }
  os << indent << "VoxelSource: " << static_cast<void*>(this->VoxelSource) << "\n";
  os << indent << "GIActive: " << this->GIActive << "\n";
  const voxelgi::VoxelGrid& grid = this->VoxelOwner()->Internal->Scan.GetGrid();
  os << indent << "Grid: " << grid.Resolution << "^3 voxels of " << grid.VoxelSize << " from ("
     << grid.Origin.x << ", " << grid.Origin.y << ", " << grid.Origin.z << ")\n";
  os << indent << "VoxelMemoryBytes: " << this->GetVoxelMemoryBytes() << "\n";
  for (int stage = 0; stage < NUMBER_OF_STAGES; ++stage)
  {
    const bool ran = this->GetStageRan(stage);
    os << indent << "Stage " << GetStageName(stage) << ": " << (ran ? "ran" : "skipped");
    if (ran && this->TimeStages)
    {
      os << ", " << this->GetStageTime(stage) << " ms";
    }
    os << "\n";
  }
}
