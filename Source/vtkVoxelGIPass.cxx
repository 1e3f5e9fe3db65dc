#include "vtkVoxelGIPass.h"

#include "ConeTracer.h"
#include "GBuffer.h"
#include "GLHelpers.h"
#include "ShadowMaps.h"
#include "VoxelDebugView.h"
#include "VoxelGrid.h"
#include "VoxelLighting.h"
#include "VoxelLights.h"
#include "VoxelMipmap.h"
#include "Voxelizer.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkDataObject.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkPropCollection.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtkFloatArray.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkVoxelGIPass);
vtkCxxSetObjectMacro(vtkVoxelGIPass, DelegatePass, vtkRenderPass);
vtkInformationKeyRestrictedMacro(vtkVoxelGIPass, EMISSION, DoubleVector, 3);
vtkInformationKeyMacro(vtkVoxelGIPass, DYNAMIC, Integer);

namespace
{
constexpr int MinResolution = 16;
constexpr int MaxResolution = 512;

// What the scan remembers of an actor between frames.
struct ActorRecord
{
  vtkWeakPointer<vtkActor> Actor;
  vtkMTimeType Signature = 0; // latest modification time of actor, mapper and input
  std::array<double, 3> Emission{ { 0.0, 0.0, 0.0 } };
  bool UserDynamic = false;
  bool Dynamic = false; // user choice, or changed after voxelization (AutoDynamic)
};

std::array<double, 3> PropEmission(vtkProp* prop)
{
  std::array<double, 3> e{ { 0.0, 0.0, 0.0 } };
  vtkInformation* info = prop->GetPropertyKeys();
  if (info && info->Has(vtkVoxelGIPass::EMISSION()))
  {
    const double* v = info->Get(vtkVoxelGIPass::EMISSION());
    for (int c = 0; c < 3; ++c)
    {
      // Keys set around SetPropEmission() may still hold bad values: never let them through.
      e[c] = std::isfinite(v[c]) ? std::max(v[c], 0.0) : 0.0;
    }
  }
  return e;
}

bool PropUserDynamic(vtkProp* prop)
{
  vtkInformation* info = prop->GetPropertyKeys();
  return info && info->Has(vtkVoxelGIPass::DYNAMIC()) && info->Get(vtkVoxelGIPass::DYNAMIC());
}

vtkInformation* EnsurePropertyKeys(vtkProp* prop)
{
  if (!prop->GetPropertyKeys())
  {
    vtkNew<vtkInformation> info;
    prop->SetPropertyKeys(info);
  }
  return prop->GetPropertyKeys();
}

vtkMTimeType ActorSignature(vtkActor* actor)
{
  vtkMTimeType t = actor->GetMTime();
  vtkMapper* mapper = actor->GetMapper();
  t = std::max(t, mapper->GetMTime());
  if (vtkDataObject* input = mapper->GetInputDataObject(0, 0))
  {
    t = std::max(t, input->GetMTime());
  }
  return t;
}
}

struct vtkVoxelGIPass::Internals
{
  // Which shader code the mappers get while this pass is in their render-pass keys.
  enum class Injection
  {
    Voxelize,
    GBuffer
  };

  voxelgi::Voxelizer Voxels;
  voxelgi::VoxelLights Lights;
  voxelgi::VoxelLighting Lighting;
  voxelgi::ShadowMaps Shadows;
  voxelgi::VoxelMipmap Mipmap;
  voxelgi::ConeSettings Cones;
  voxelgi::GBuffer Frame;
  voxelgi::ConeTracer Tracer;
  voxelgi::VoxelDebugView Debug;
  // Camera + lights + opaque steps of a vtkRenderStepsPass delegate, into the G-buffer.
  vtkNew<vtkCameraPass> OpaqueCamera;
  vtkNew<vtkSequencePass> OpaqueSequence;
  vtkNew<vtkRenderPassCollection> OpaquePasses;
  Injection Mode = Injection::Voxelize;
  bool LitScene = true;
  std::vector<double> RadianceSettings; // what the radiance was last computed with
  bool RadianceValid = false;
  bool Traced = false;
  bool WarnedLights = false;
  bool WarnedUnlit = false;
  bool WarnedInvalidLights = false;
  std::size_t WarnedLeftOut = 0;
  bool AnySpecular = false;
  bool InvalidateRequested = false;
  int FramesSinceUpdate = 0;
  bool VoxelizedThisFrame = false;
  std::vector<unsigned long long> LastFrameKey; // what the last traced image depended on
  voxelgi::EmptyFramebuffer Framebuffer;
  voxelgi::VoxelGrid Grid;
  std::array<voxelgi::StageTimer, NUMBER_OF_STAGES> Timers;
  std::array<bool, NUMBER_OF_STAGES> Ran{};
  std::array<double, NUMBER_OF_STAGES> Times{};
  std::vector<ActorRecord> Records;
  double EmissionScale = 0.0;
  double FittedPadding = -1.0;
  bool Voxelized = false;
  bool StaticPass = false;
  vtkNew<vtkCamera> VoxelCamera;
  vtkTimeStamp ShaderStageTime;
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  bool ContextChecked = false;
  bool ContextOk = false;
  bool HasConservativeRaster = false;

  void SetMode(Injection mode)
  {
    if (mode != this->Mode)
    {
      this->Mode = mode;
      this->ShaderStageTime.Modified(); // mappers rebuild their shaders for the other mode
    }
  }

  void BeginStage(int stage, bool timed)
  {
    this->Ran[stage] = true;
    if (timed)
    {
      this->Timers[stage].Begin();
    }
  }
  void EndStage(int stage, bool timed)
  {
    if (timed)
    {
      this->Timers[stage].End();
    }
  }
};

//------------------------------------------------------------------------------
vtkVoxelGIPass::vtkVoxelGIPass()
  : Internal(new Internals)
{
  vtkNew<vtkRenderStepsPass> steps;
  this->SetDelegatePass(steps);
  this->Internal->OpaqueSequence->SetPasses(this->Internal->OpaquePasses);
  this->Internal->OpaqueCamera->SetDelegatePass(this->Internal->OpaqueSequence);
}

vtkVoxelGIPass::~vtkVoxelGIPass()
{
  this->SetDelegatePass(nullptr);
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
              << voxelgi::Voxelizer::RequiredBytes(resolution, false) / (1024 * 1024)
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
  if (!prop)
  {
    return;
  }
  const double rgb[3] = { r, g, b };
  for (double v : rgb)
  {
    if (!std::isfinite(v) || v < 0.0)
    {
      vtkGenericWarningMacro(<< "vtkVoxelGIPass::SetPropEmission: emission (" << r << ", " << g
                             << ", " << b
                             << ") must be finite and non-negative; the prop's emission is left "
                                "unchanged.");
      return;
    }
  }
  vtkInformation* info = EnsurePropertyKeys(prop);
  if (r == 0.0 && g == 0.0 && b == 0.0)
  {
    info->Remove(EMISSION());
  }
  else
  {
    info->Set(EMISSION(), rgb, 3);
  }
}

void vtkVoxelGIPass::SetPropDynamic(vtkProp* prop, bool dynamic)
{
  if (prop)
  {
    EnsurePropertyKeys(prop)->Set(DYNAMIC(), dynamic ? 1 : 0);
  }
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::GetStageRan(int stage) const
{
  return stage >= 0 && stage < NUMBER_OF_STAGES && this->Internal->Ran[stage];
}

double vtkVoxelGIPass::GetStageTime(int stage) const
{
  return (stage >= 0 && stage < NUMBER_OF_STAGES) ? this->Internal->Times[stage] : 0.0;
}

const char* vtkVoxelGIPass::GetStageName(int stage)
{
  static const char* names[NUMBER_OF_STAGES] = { "Scan", "Clear", "VoxelizeStatic",
    "VoxelizeDynamic", "Resolve", "ShadowMaps", "LightVoxels", "Mipmap", "Bounce", "GBuffer",
    "ConeTrace", "Present", "DebugView" };
  return (stage >= 0 && stage < NUMBER_OF_STAGES) ? names[stage] : "Unknown";
}

int vtkVoxelGIPass::GetGridResolution() const
{
  return this->Internal->Grid.Resolution;
}

void vtkVoxelGIPass::GetGridOrigin(double origin[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    origin[a] = this->Internal->Grid.Origin[a];
  }
}

double vtkVoxelGIPass::GetGridVoxelSize() const
{
  return this->Internal->Grid.VoxelSize;
}

bool vtkVoxelGIPass::GetUsedHardwareConservativeRaster() const
{
  return this->Internal->Voxels.GetHardwareConservative();
}

void vtkVoxelGIPass::Invalidate()
{
  this->Internal->InvalidateRequested = true;
}

unsigned long long vtkVoxelGIPass::GetAllocatedBytes(int resource) const
{
  const Internals& in = *this->Internal;
  switch (resource)
  {
    case RESOURCE_VOXELIZATION:
      return in.Voxels.MemoryBytes() - in.Voxels.EmissionBytes();
    case RESOURCE_EMISSION:
      return in.Voxels.EmissionBytes();
    case RESOURCE_RADIANCE:
      return in.Lighting.Radiance.Bytes();
    case RESOURCE_DIRECT:
      return in.Lighting.Direct.Bytes();
    case RESOURCE_DIRECTIONAL:
      return in.Mipmap.MemoryBytes();
    case RESOURCE_SHADOW_MAPS:
      return in.Shadows.Maps.Bytes();
    default:
      return 0;
  }
}

unsigned long long vtkVoxelGIPass::GetVoxelMemoryBytes() const
{
  const Internals& in = *this->Internal;
  return in.Voxels.MemoryBytes() + in.Lighting.MemoryBytes() + in.Mipmap.MemoryBytes() +
    in.Shadows.Maps.Bytes();
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::CheckContext(vtkRenderWindow* renWin)
{
  Internals& in = *this->Internal;
  if (in.ContextChecked && renWin == in.Window.GetPointer())
  {
    return in.ContextOk;
  }
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  // VOXELGI_SIMULATE_GL_VERSION=3.2 makes the check see an older context (for tests).
  if (const char* simulated = std::getenv("VOXELGI_SIMULATE_GL_VERSION"))
  {
    major = std::atoi(simulated);
    const char* dot = std::strchr(simulated, '.');
    minor = dot ? std::atoi(dot + 1) : 0;
  }
  in.ContextChecked = true;
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
void vtkVoxelGIPass::Render(const vtkRenderState* s)
{
  Internals& in = *this->Internal;
  this->NumberOfRenderedProps = 0;
  in.Ran.fill(false);
  in.Times.fill(0.0);
  this->GIActive = false;

  const bool traced = in.Traced;
  in.Traced = false;
  in.VoxelizedThisFrame = false;
  vtkRenderer* renderer = s->GetRenderer();
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  bool voxelsChanged = false;
  bool radianceChanged = false;
  // Hardware picking renders through the pass too: it must see VTK's plain render steps.
  if (this->Enabled && renWin && !renderer->GetSelector() && this->CheckContext(renWin))
  {
    in.Window = renWin;
    this->GIActive = this->UpdateVoxels(s, voxelsChanged) &&
      this->UpdateRadiance(renderer, voxelsChanged, radianceChanged);
  }

  const bool voxelView = this->DebugView >= DEBUG_VIEW_VOXEL_ALBEDO &&
    this->DebugView <= DEBUG_VIEW_VOXEL_RADIANCE;
  if (!this->GIActive || voxelView)
  {
    in.LastFrameKey.clear();
    this->RenderDelegate(s);
  }
  else
  {
    // Everything the traced image depends on; unchanged, it is presented again.
    std::vector<unsigned long long> key{ renderer->GetMTime(), this->GetMTime(),
      renderer->GetActiveCamera()->GetMTime() };
    int size[4];
    renderer->GetTiledSizeAndOrigin(size, size + 1, size + 2, size + 3);
    key.insert(key.end(), size, size + 4);
    vtkCollectionSimpleIterator it;
    renderer->GetViewProps()->InitTraversal(it);
    while (vtkProp* prop = renderer->GetViewProps()->GetNextProp(it))
    {
      vtkActor* actor = vtkActor::SafeDownCast(prop);
      key.push_back(actor && actor->GetMapper() ? ActorSignature(actor) : prop->GetMTime());
      key.push_back(prop->GetVisibility());
    }
    const bool reuse = traced && !voxelsChanged && !radianceChanged && key == in.LastFrameKey;
    in.LastFrameKey = key;
    this->RenderGI(s, reuse);
  }

  if (this->GIActive && voxelView)
  {
    in.BeginStage(STAGE_DEBUG_VIEW, this->TimeStages);
    in.Debug.Render(renderer, in.Grid, in.Voxels, in.Lighting.Radiance, this->DebugView);
    in.EndStage(STAGE_DEBUG_VIEW, this->TimeStages);
  }

  // Changes made while voxelizing and rendering (a mapper creating its default lookup table,
  // say) are part of this frame, not news for the next one.
  if (in.VoxelizedThisFrame)
  {
    for (ActorRecord& record : in.Records)
    {
      if (record.Actor)
      {
        record.Signature = ActorSignature(record.Actor);
      }
    }
  }

  if (this->TimeStages)
  {
    for (int stage = STAGE_SCAN + 1; stage < NUMBER_OF_STAGES; ++stage) // the scan is CPU time
    {
      in.Times[stage] = in.Ran[stage] ? in.Timers[stage].Milliseconds() : 0.0;
    }
  }
}

//------------------------------------------------------------------------------
void vtkVoxelGIPass::RenderDelegate(const vtkRenderState* s)
{
  if (this->DelegatePass)
  {
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
  }
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::UpdateVoxels(const vtkRenderState* s, bool& changed)
{
  Internals& in = *this->Internal;
  vtkRenderer* renderer = s->GetRenderer();
  // CPU time of the scene scan and change detection (not of the GPU work it then issues).
  const auto scanStart = std::chrono::steady_clock::now();
  auto endScan = [&in, scanStart]() {
    in.Ran[STAGE_SCAN] = true;
    in.Times[STAGE_SCAN] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - scanStart).count();
  };

  // Scene scan: every visible opaque surface actor drawn by a polydata mapper, including
  // the ones outside the view frustum (they still cast and reflect light).
  std::unordered_map<vtkActor*, ActorRecord> previous;
  for (const ActorRecord& record : in.Records)
  {
    if (record.Actor)
    {
      previous[record.Actor] = record;
    }
  }
  std::vector<ActorRecord> records;
  double bounds[6];
  vtkMath::UninitializeBounds(bounds);
  bool haveBounds = false;
  std::size_t leftOut = 0; // visible 3D props VTK renders without GI
  bool anySpecular = false;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (!prop->GetVisibility())
    {
      continue;
    }
    // Empty props (e.g. ParaView's selection and axes actors) are neither voxelized nor worth a
    // warning.
    const double* propBounds = prop->GetBounds();
    if (!propBounds || !vtkMath::AreBoundsInitialized(propBounds))
    {
      continue;
    }
    vtkActor* actor = vtkActor::SafeDownCast(prop);
    if (!actor)
    {
      leftOut += prop->IsA("vtkVolume") ? 1 : 0;
      continue;
    }
    if (!vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper()) ||
      actor->GetProperty()->GetRepresentation() != VTK_SURFACE)
    {
      ++leftOut;
      continue;
    }
    if (!actor->HasOpaqueGeometry())
    {
      ++leftOut; // translucent
      continue;
    }
    const double* b = propBounds;
    if (!std::all_of(b, b + 6, [](double v) { return std::isfinite(v); }))
    {
      vtkWarningMacro(<< "An actor has non-finite bounds (NaN or Inf coordinates); it is left "
                         "out of the voxel grid.");
      continue;
    }
    EnsurePropertyKeys(actor);
    ActorRecord record;
    record.Actor = actor;
    record.Signature = ActorSignature(actor);
    auto found = previous.find(actor);
    if (found == previous.end() || record.Signature > found->second.Signature)
    {
      this->ReportNonFinitePoints(actor); // new or changed input: check it once
    }
    record.Emission = PropEmission(actor);
    record.UserDynamic = PropUserDynamic(actor);
    record.Dynamic = record.UserDynamic || (found != previous.end() && found->second.Dynamic);
    for (int i = 0; i < 3; ++i)
    {
      bounds[2 * i] = haveBounds ? std::min(bounds[2 * i], b[2 * i]) : b[2 * i];
      bounds[2 * i + 1] = haveBounds ? std::max(bounds[2 * i + 1], b[2 * i + 1]) : b[2 * i + 1];
    }
    haveBounds = true;
    anySpecular = anySpecular || actor->GetProperty()->GetSpecular() > 0.0;
    records.push_back(record);
  }
  if (leftOut > in.WarnedLeftOut)
  {
    vtkWarningMacro(<< leftOut
                    << " visible props (translucent, volume, points or wireframe) are rendered "
                       "by VTK without voxel GI.");
    in.WarnedLeftOut = leftOut;
  }
  in.AnySpecular = anySpecular;
  if (records.empty())
  {
    endScan();
    in.Records.clear();
    return false;
  }

  // Change detection against the end of the last frame.
  bool full = !in.Voxelized || records.size() != in.Records.size();
  bool dynamicChanged = false;
  for (std::size_t i = 0; i < records.size(); ++i)
  {
    ActorRecord& record = records[i];
    if (full || in.Records[i].Actor.GetPointer() != record.Actor.GetPointer())
    {
      full = true;
      continue;
    }
    const ActorRecord& old = in.Records[i];
    const bool changed = record.Signature > old.Signature || record.Emission != old.Emission;
    if (record.UserDynamic != old.UserDynamic)
    {
      full = true; // the static/dynamic split itself changed
    }
    else if (changed && record.Dynamic)
    {
      dynamicChanged = true;
    }
    else if (changed)
    {
      full = true;
      record.Dynamic = this->AutoDynamic != 0;
    }
  }

  double emissionScale = 0.0;
  for (const ActorRecord& record : records)
  {
    emissionScale = std::max(
      { emissionScale, record.Emission[0], record.Emission[1], record.Emission[2] });
  }
  // Emission is stored relative to the scene's brightest emitter.
  if (emissionScale != in.EmissionScale)
  {
    full = true;
  }

  const bool emission = emissionScale > 0.0;
  const bool hardware = this->HardwareConservativeRaster && in.HasConservativeRaster;
  // Changes of the voxel settings (and the first frame) always rebuild; changes of the scene
  // follow the update policy.
  const bool settingsChanged = !in.Voxelized || !in.Grid.IsValid() ||
    in.Grid.Resolution != this->VoxelResolution || in.FittedPadding != this->GridPadding ||
    emission != in.Voxels.HasEmission() || hardware != in.Voxels.GetHardwareConservative();
  // The scene left the grid or shrank to under half of it.
  const double extent = std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  const bool refit = settingsChanged || !in.Grid.Covers(bounds) ||
    extent * (1.0 + 2.0 * this->GridPadding) < 0.5 * in.Grid.Size();
  const bool pending = full || dynamicChanged || refit;
  bool due = settingsChanged || in.InvalidateRequested;
  switch (this->UpdatePolicy)
  {
    case UPDATE_EVERY_FRAME:
      due = true;
      full = true;
      break;
    case UPDATE_EVERY_N_FRAMES:
      due = due || (pending && in.FramesSinceUpdate + 1 >= this->UpdateInterval);
      break;
    case UPDATE_ON_DEMAND:
      break;
    default:
      due = due || pending;
      break;
  }
  endScan();
  if (!due)
  {
    // Keep the voxels and the records they were built from: the change stays pending.
    ++in.FramesSinceUpdate;
    changed = false;
    return true;
  }
  full = full || refit || in.InvalidateRequested;
  in.InvalidateRequested = false;
  in.FramesSinceUpdate = 0;

  voxelgi::VoxelGrid grid = in.Grid;
  if (refit && voxelgi::FitVoxelGrid(bounds, this->VoxelResolution, this->GridPadding, grid) !=
      voxelgi::FitStatus::Ok)
  {
    vtkErrorMacro(<< "Could not fit a voxel grid around the scene bounds; rendering without GI.");
    in.Records.clear();
    return false;
  }
  if (emission != in.Voxels.HasEmission() || grid.Resolution != in.Voxels.GetResolution())
  {
    std::string error;
    if (!in.Voxels.Prepare(grid.Resolution, emission, error))
    {
      vtkErrorMacro(<< "Voxel GI disabled for this frame: " << error << ".");
      in.Records.clear();
      in.Voxelized = false;
      return false;
    }
    in.ShaderStageTime.Modified(); // the mapper shaders depend on the emission variant
  }
  in.Voxels.SetHardwareConservative(hardware);

  in.Grid = grid;
  in.FittedPadding = this->GridPadding;
  in.EmissionScale = emissionScale;
  in.Records = records;

  changed = true;
  this->VoxelizeActors(renderer, full);
  in.Voxelized = true;
  in.VoxelizedThisFrame = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkVoxelGIPass::ReportNonFinitePoints(vtkActor* actor)
{
  vtkPolyData* poly = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0));
  vtkPoints* points = poly ? poly->GetPoints() : nullptr;
  if (!points)
  {
    return;
  }
  vtkIdType bad = 0;
  double p[3];
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    points->GetPoint(i, p);
    bad += (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) ? 0 : 1;
  }
  if (bad > 0)
  {
    vtkWarningMacro(<< "An actor has " << bad << " of " << points->GetNumberOfPoints()
                    << " points with NaN or Inf coordinates; its triangles that use them are "
                       "not voxelized.");
  }
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::UpdateRadiance(vtkRenderer* renderer, bool voxelsChanged, bool& changed)
{
  Internals& in = *this->Internal;
  vtkOpenGLRenderWindow* renWin = in.Window;
  const bool timed = this->TimeStages != 0;

  // VTK creates its automatic headlight and places headlights and camera lights while
  // rendering; do both before reading the lights, or the first frame would see none.
  if (renderer->GetAutomaticLightCreation() && renderer->GetLights()->GetNumberOfItems() == 0)
  {
    renderer->CreateLight();
  }
  renderer->UpdateLightsGeometryToFollowCamera();
  int dropped = 0, invalid = 0;
  const bool lightsChanged = in.Lights.Gather(renderer, in.Grid, dropped, invalid);
  if (invalid > 0 && !in.WarnedInvalidLights)
  {
    vtkWarningMacro(<< invalid << " light(s) with a negative or non-finite intensity or colour "
                                   "are left out of the GI.");
    in.WarnedInvalidLights = true;
  }
  if (dropped > 0 && !in.WarnedLights)
  {
    vtkWarningMacro(<< "Voxel GI uses the first " << voxelgi::VoxelLights::MaxLights
                    << " lights; " << dropped << " more are left out of the GI.");
    in.WarnedLights = true;
  }
  in.LitScene = in.Lights.GetCount() > 0;
  changed = false;
  if (!in.LitScene && !in.Voxels.HasEmission())
  {
    if (!in.WarnedUnlit)
    {
      vtkWarningMacro(<< "The scene has no light and no emissive prop: nothing to illuminate, "
                         "rendering without GI.");
      in.WarnedUnlit = true;
    }
    in.RadianceValid = false;
    return false;
  }
  in.Lights.Bind();

  const double maxDistance = this->MaxTraceDistance * in.Grid.Resolution;
  in.Cones.Set(this->DiffuseConeCount, this->DiffuseConeAperture, this->ConeStepFactor, maxDistance);
  const std::vector<double> settings{ static_cast<double>(this->LightOcclusion),
    static_cast<double>(this->ShadowMapResolution),
    static_cast<double>(this->Bounces), static_cast<double>(this->AnisotropicMipmaps),
    static_cast<double>(this->DiffuseConeCount), this->DiffuseConeAperture, this->ConeStepFactor,
    maxDistance };
  if (!voxelsChanged && !lightsChanged && in.RadianceValid && settings == in.RadianceSettings)
  {
    return true;
  }
  changed = true;

  std::string error;
  const int res = in.Grid.Resolution;
  const bool anisotropic = this->AnisotropicMipmaps != 0;
  if (!in.Lighting.Prepare(res, !anisotropic, this->Bounces > 0, error) ||
    !in.Mipmap.Prepare(res, anisotropic, error))
  {
    vtkErrorMacro(<< "Voxel GI disabled for this frame: " << error << ".");
    in.RadianceValid = false;
    return false;
  }
  const voxelgi::ShadowMaps* shadowMaps = nullptr;
  if (this->LightOcclusion == LIGHT_OCCLUSION_SHADOW_MAPS)
  {
    in.BeginStage(STAGE_SHADOW_MAPS, timed);
    std::vector<vtkProp*> casters;
    for (const ActorRecord& record : in.Records)
    {
      if (record.Actor)
      {
        casters.push_back(record.Actor);
      }
    }
    if (!in.Shadows.Render(renderer, in.Lights.GetLights(), casters, in.Grid,
          this->ShadowMapResolution, error))
    {
      vtkErrorMacro(<< "Voxel GI disabled for this frame: " << error << ".");
      in.RadianceValid = false;
      return false;
    }
    in.EndStage(STAGE_SHADOW_MAPS, timed);
    shadowMaps = &in.Shadows;
  }
  else
  {
    in.Shadows.ReleaseGraphicsResources();
  }
  in.BeginStage(STAGE_LIGHT, timed);
  const bool injected = in.Lighting.Inject(renWin, in.Voxels,
    this->LightOcclusion != LIGHT_OCCLUSION_NONE, shadowMaps, error);
  in.EndStage(STAGE_LIGHT, timed);
  if (!injected)
  {
    vtkErrorMacro(<< "Voxel GI disabled for this frame: " << error << ".");
    in.RadianceValid = false;
    return false;
  }
  in.BeginStage(STAGE_MIPMAP, timed);
  in.Mipmap.Build(renWin, in.Lighting.Radiance);
  in.EndStage(STAGE_MIPMAP, timed);
  if (this->Bounces > 0)
  {
    // Bounce and mip timings are summed into one query each would nest; time them together.
    in.BeginStage(STAGE_BOUNCE, timed);
    for (int bounce = 0; bounce < this->Bounces; ++bounce)
    {
      in.Lighting.Bounce(renWin, in.Voxels, in.Mipmap, in.Cones);
      in.Mipmap.Build(renWin, in.Lighting.Radiance);
    }
    in.EndStage(STAGE_BOUNCE, timed);
  }
  in.RadianceSettings = settings;
  in.RadianceValid = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkVoxelGIPass::RenderGI(const vtkRenderState* s, bool reuse)
{
  Internals& in = *this->Internal;
  vtkRenderer* renderer = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = in.Window;
  const bool timed = this->TimeStages != 0;
  int width = 0, height = 0, x = 0, y = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  if (width <= 0 || height <= 0)
  {
    return;
  }

  vtkRenderStepsPass* steps = vtkRenderStepsPass::SafeDownCast(this->DelegatePass);
  if (!reuse)
  {
    this->TraceFrame(s, steps, width, height);
  }
  in.Traced = true;

  in.BeginStage(STAGE_PRESENT, timed);
  {
    vtkOpenGLState* ostate = renWin->GetState();
    vtkOpenGLState::ScopedglViewport viewport(ostate);
    vtkOpenGLState::ScopedglScissor scissor(ostate);
    vtkOpenGLState::ScopedglEnableDisable scissorTest(ostate, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
    ostate->vtkglEnable(GL_SCISSOR_TEST);
    in.Tracer.Present(renWin, in.Frame, x, y, width, height);

    // VTK's remaining steps draw over the composite, depth-tested against the scene.
    if (steps)
    {
      ostate->vtkglEnable(GL_DEPTH_TEST);
      for (vtkRenderPass* pass : { steps->GetTranslucentPass(), steps->GetVolumetricPass(),
             steps->GetOverlayPass(), steps->GetPostProcessPass() })
      {
        if (pass)
        {
          pass->Render(s);
          this->NumberOfRenderedProps += pass->GetNumberOfRenderedProps();
        }
      }
    }
  }
  in.EndStage(STAGE_PRESENT, timed);
}

//------------------------------------------------------------------------------
void vtkVoxelGIPass::TraceFrame(
  const vtkRenderState* s, vtkRenderStepsPass* steps, int width, int height)
{
  Internals& in = *this->Internal;
  vtkRenderer* renderer = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = in.Window;
  const bool timed = this->TimeStages != 0;

  // G-buffer: VTK's camera, lights and opaque steps (the whole delegate if it is not a
  // vtkRenderStepsPass) into the pass's framebuffer.
  in.BeginStage(STAGE_GBUFFER, timed);
  in.Frame.Prepare(renWin, width, height);
  vtkRenderPass* opaque = this->DelegatePass;
  if (steps)
  {
    vtkRenderPassCollection* passes = in.OpaquePasses;
    passes->RemoveAllItems();
    for (vtkRenderPass* pass : { steps->GetLightsPass(), steps->GetOpaquePass() })
    {
      if (pass)
      {
        passes->AddItem(pass);
      }
    }
    opaque = in.OpaqueCamera;
  }
  vtkRenderState frameState(renderer);
  frameState.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
  frameState.SetFrameBuffer(in.Frame.GetFramebuffer());
  in.SetMode(Internals::Injection::GBuffer);
  this->PreRender(&frameState);
  in.Frame.Begin();
  if (opaque)
  {
    opaque->Render(&frameState);
    this->NumberOfRenderedProps += opaque->GetNumberOfRenderedProps();
  }
  in.Frame.End();
  this->PostRender(&frameState);
  in.EndStage(STAGE_GBUFFER, timed);

  in.BeginStage(STAGE_CONE_TRACE, timed);
  voxelgi::TraceSettings trace;
  trace.StartOffset = static_cast<float>(this->ConeStartOffset);
  trace.IndirectIntensity = static_cast<float>(this->IndirectIntensity);
  trace.SpecularIntensity = static_cast<float>(this->SpecularIntensity);
  // No specular material in the scene: no specular cone.
  trace.SpecularCone = this->SpecularCone && in.AnySpecular;
  trace.AOStrength = static_cast<float>(this->AmbientOcclusionStrength);
  trace.AOFalloff = static_cast<float>(this->AmbientOcclusionFalloff);
  trace.ConeShadows = this->ConeShadows != 0;
  trace.ShadowTanHalf =
    static_cast<float>(std::tan(vtkMath::RadiansFromDegrees(0.5 * this->ShadowConeAperture)));
  trace.View = this->DebugView >= DEBUG_VIEW_DIRECT ? this->DebugView - DEBUG_VIEW_DIRECT + 1 : 0;
  trace.Scale = static_cast<float>(this->TraceResolution);
  in.Lights.Bind();
  in.Tracer.Trace(renderer, in.Grid, in.Frame, in.Lighting, in.Mipmap, in.Cones, trace);
  in.EndStage(STAGE_CONE_TRACE, timed);
}

//------------------------------------------------------------------------------
void vtkVoxelGIPass::VoxelizeActors(vtkRenderer* renderer, bool full)
{
  Internals& in = *this->Internal;
  vtkOpenGLRenderWindow* renWin = in.Window;
  vtkOpenGLState* ostate = renWin->GetState();
  const bool timed = this->TimeStages != 0;
  const int res = in.Grid.Resolution;

  in.BeginStage(STAGE_CLEAR, timed);
  in.Voxels.Clear(renWin, full);
  in.EndStage(STAGE_CLEAR, timed);

  std::vector<vtkProp*> staticProps;
  std::vector<vtkProp*> dynamicProps;
  for (const ActorRecord& record : in.Records)
  {
    (record.Dynamic ? dynamicProps : staticProps).push_back(record.Actor);
  }
  std::vector<vtkProp*> all(staticProps);
  all.insert(all.end(), dynamicProps.begin(), dynamicProps.end());

  // An orthographic camera whose view volume is the grid cube: VTK's mappers then compose
  // model, shift-scale and grid matrices in double precision for us.
  const glm::dvec3 center = in.Grid.Center();
  const double half = 0.5 * in.Grid.Size();
  vtkCamera* camera = in.VoxelCamera;
  camera->SetFocalPoint(center.x, center.y, center.z);
  camera->SetPosition(center.x, center.y, center.z + half);
  camera->SetViewUp(0.0, 1.0, 0.0);
  vtkNew<vtkMatrix4x4> projection;
  projection->SetElement(0, 0, 1.0 / half);
  projection->SetElement(1, 1, 1.0 / half);
  projection->SetElement(2, 2, 1.0 / half);
  projection->SetElement(2, 3, 1.0);
  camera->SetExplicitProjectionTransformMatrix(projection);
  camera->SetUseExplicitProjectionTransformMatrix(true);

  vtkCamera* userCamera = renderer->GetActiveCamera();
  userCamera->Register(this);
  renderer->SetActiveCamera(camera);

  ostate->PushFramebufferBindings();
  ostate->vtkglBindFramebuffer(GL_FRAMEBUFFER, in.Framebuffer.Prepare(res, res));
  {
    vtkOpenGLState::ScopedglViewport viewport(ostate);
    vtkOpenGLState::ScopedglEnableDisable scissor(ostate, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglEnableDisable depth(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable cull(ostate, GL_CULL_FACE);
    ostate->vtkglViewport(0, 0, res, res);
    ostate->vtkglDisable(GL_SCISSOR_TEST);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    ostate->vtkglDisable(GL_BLEND);
    // Depth is computed in the shader; clamping keeps the rasterizer from clipping it.
    glEnable(GL_DEPTH_CLAMP);
    const bool hardware = in.Voxels.GetHardwareConservative();
    if (hardware)
    {
      glEnable(GL_CONSERVATIVE_RASTERIZATION_NV);
    }

    vtkRenderState state(renderer);
    state.SetPropArrayAndCount(all.data(), static_cast<int>(all.size()));
    in.SetMode(Internals::Injection::Voxelize);
    this->PreRender(&state);
    in.Voxels.BindForRendering();
    if (full)
    {
      in.BeginStage(STAGE_VOXELIZE_STATIC, timed);
      in.StaticPass = true;
      for (vtkProp* prop : staticProps)
      {
        prop->RenderOpaqueGeometry(renderer);
      }
      voxelgi::Voxelizer::Barrier();
      in.EndStage(STAGE_VOXELIZE_STATIC, timed);
    }
    if (!dynamicProps.empty())
    {
      in.BeginStage(STAGE_VOXELIZE_DYNAMIC, timed);
      in.StaticPass = false;
      in.Voxels.BindForRendering();
      for (vtkProp* prop : dynamicProps)
      {
        prop->RenderOpaqueGeometry(renderer);
      }
      voxelgi::Voxelizer::Barrier();
      in.EndStage(STAGE_VOXELIZE_DYNAMIC, timed);
    }
    this->PostRender(&state);
    glDisable(GL_DEPTH_CLAMP);
    if (hardware)
    {
      glDisable(GL_CONSERVATIVE_RASTERIZATION_NV);
    }
  }
  ostate->PopFramebufferBindings();

  renderer->SetActiveCamera(userCamera);
  userCamera->UnRegister(this);

  // Line and point primitives of mixed polydata cannot feed the triangle geometry shader;
  // GL rejects those draws (they have no area to voxelize). Do not leave the errors to VTK.
  voxelgi::ClearErrors();

  in.BeginStage(STAGE_RESOLVE, timed);
  in.Voxels.Resolve(renWin, static_cast<float>(in.EmissionScale));
  in.EndStage(STAGE_RESOLVE, timed);
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::PreReplaceShaderValues(std::string&, std::string& geometryShader,
  std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  if (this->Internal->Mode == Internals::Injection::Voxelize)
  {
    voxelgi::Voxelizer::PreReplaceShaders(geometryShader, fragmentShader);
  }
  return true;
}

bool vtkVoxelGIPass::PostReplaceShaderValues(std::string&, std::string& geometryShader,
  std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  Internals& in = *this->Internal;
  if (in.Mode == Internals::Injection::Voxelize)
  {
    in.Voxels.PostReplaceShaders(geometryShader, fragmentShader);
  }
  else if (vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    voxelgi::GBuffer::PostReplaceShaders(fragmentShader, prop, in.LitScene);
  }
  return true;
}

bool vtkVoxelGIPass::SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper,
  vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  Internals& in = *this->Internal;
  if (in.Mode == Internals::Injection::GBuffer)
  {
    in.Frame.SetShaderParameters(mapper);
    return true;
  }
  std::array<double, 3> emission = PropEmission(prop);
  for (double& e : emission)
  {
    e = in.EmissionScale > 0.0 ? e / in.EmissionScale : 0.0;
  }
  in.Voxels.SetShaderParameters(program, in.StaticPass, emission.data());
  return true;
}

vtkMTimeType vtkVoxelGIPass::GetShaderStageMTime()
{
  return this->Internal->ShaderStageTime.GetMTime();
}

//------------------------------------------------------------------------------
bool vtkVoxelGIPass::GetFloatImage(int image, vtkFloatArray* pixels)
{
  Internals& in = *this->Internal;
  std::vector<float> rgba;
  int w = 0, h = 0;
  if (!pixels || !in.Window || !in.Traced || !in.Tracer.Read(in.Window, image, rgba, w, h))
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
  Internals& in = *this->Internal;
  const int res = in.Voxels.GetResolution();
  if (!image || !in.Window || res <= 0 || (volume == VOLUME_EMISSION && !in.Voxels.HasEmission()) ||
    (volume == VOLUME_RADIANCE && !in.Lighting.Radiance.IsAllocated()))
  {
    return false;
  }
  in.Window->MakeCurrent();
  image->Initialize();
  image->SetDimensions(res, res, res);
  image->SetSpacing(in.Grid.VoxelSize, in.Grid.VoxelSize, in.Grid.VoxelSize);
  const double h = 0.5 * in.Grid.VoxelSize;
  image->SetOrigin(in.Grid.Origin.x + h, in.Grid.Origin.y + h, in.Grid.Origin.z + h);
  const vtkIdType n = static_cast<vtkIdType>(res) * res * res;
  vtkSmartPointer<vtkDataArray> array;
  switch (volume)
  {
    case VOLUME_ALBEDO:
    case VOLUME_NORMAL:
    {
      auto bytes = vtkSmartPointer<vtkUnsignedCharArray>::New();
      bytes->SetNumberOfComponents(4);
      bytes->SetNumberOfTuples(n);
      (volume == VOLUME_ALBEDO ? in.Voxels.AlbedoVolume : in.Voxels.NormalVolume)
        .Read(GL_RGBA, GL_UNSIGNED_BYTE, bytes->GetPointer(0));
      array = bytes;
      break;
    }
    case VOLUME_EMISSION:
    case VOLUME_RADIANCE:
    {
      auto floats = vtkSmartPointer<vtkFloatArray>::New();
      floats->SetNumberOfComponents(4);
      floats->SetNumberOfTuples(n);
      (volume == VOLUME_EMISSION ? in.Voxels.EmissionVolume : in.Lighting.Radiance)
        .Read(GL_RGBA, GL_FLOAT, floats->GetPointer(0));
      array = floats;
      break;
    }
    case VOLUME_COUNT:
    {
      std::vector<unsigned int> counts;
      in.Voxels.ReadCounts(counts);
      auto uints = vtkSmartPointer<vtkTypeUInt32Array>::New();
      uints->SetNumberOfTuples(n);
      std::copy(counts.begin(), counts.end(), uints->GetPointer(0));
      array = uints;
      break;
    }
    case VOLUME_FLAG:
    {
      std::vector<unsigned char> flags;
      in.Voxels.ReadFlags(flags);
      auto bytes = vtkSmartPointer<vtkUnsignedCharArray>::New();
      bytes->SetNumberOfTuples(n);
      std::copy(flags.begin(), flags.end(), bytes->GetPointer(0));
      array = bytes;
      break;
    }
    default:
      return false;
  }
  array->SetName("Voxels");
  image->GetPointData()->SetScalars(array);
  return true;
}

//------------------------------------------------------------------------------
void vtkVoxelGIPass::ReleaseGraphicsResources(vtkWindow* w)
{
  Internals& in = *this->Internal;
  in.Voxels.ReleaseGraphicsResources();
  in.Lights.ReleaseGraphicsResources();
  in.Lighting.ReleaseGraphicsResources();
  in.Shadows.ReleaseGraphicsResources();
  in.Mipmap.ReleaseGraphicsResources();
  in.Frame.ReleaseGraphicsResources(w);
  in.Tracer.ReleaseGraphicsResources(w);
  in.Debug.ReleaseGraphicsResources(w);
  in.RadianceValid = false;
  in.Traced = false;
  in.Framebuffer.Release();
  for (auto& timer : in.Timers)
  {
    timer.Release();
  }
  in.Voxelized = false;
  in.Records.clear();
  in.Grid = voxelgi::VoxelGrid();
  in.ContextChecked = false;
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
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
  os << indent << "Enabled: " << this->Enabled << "\n";
  os << indent << "VoxelResolution: " << this->VoxelResolution << "\n";
  os << indent << "GridPadding: " << this->GridPadding << "\n";
  os << indent << "DebugView: " << this->DebugView << "\n";
  os << indent << "AutoDynamic: " << this->AutoDynamic << "\n";
  os << indent << "UpdatePolicy: " << this->UpdatePolicy << "\n";
  os << indent << "UpdateInterval: " << this->UpdateInterval << "\n";
  os << indent << "HardwareConservativeRaster: " << this->HardwareConservativeRaster << "\n";
  os << indent << "TimeStages: " << this->TimeStages << "\n";
  os << indent << "LightOcclusion: " << this->LightOcclusion << "\n";
  os << indent << "ShadowMapResolution: " << this->ShadowMapResolution << "\n";
  os << indent << "Bounces: " << this->Bounces << "\n";
  os << indent << "AnisotropicMipmaps: " << this->AnisotropicMipmaps << "\n";
  os << indent << "DiffuseConeCount: " << this->DiffuseConeCount << "\n";
  os << indent << "DiffuseConeAperture: " << this->DiffuseConeAperture << "\n";
  os << indent << "ConeStepFactor: " << this->ConeStepFactor << "\n";
  os << indent << "MaxTraceDistance: " << this->MaxTraceDistance << "\n";
  os << indent << "ConeStartOffset: " << this->ConeStartOffset << "\n";
  os << indent << "TraceResolution: " << this->TraceResolution << "\n";
  os << indent << "IndirectIntensity: " << this->IndirectIntensity << "\n";
  os << indent << "SpecularCone: " << this->SpecularCone << "\n";
  os << indent << "SpecularIntensity: " << this->SpecularIntensity << "\n";
  os << indent << "AmbientOcclusionStrength: " << this->AmbientOcclusionStrength << "\n";
  os << indent << "AmbientOcclusionFalloff: " << this->AmbientOcclusionFalloff << "\n";
  os << indent << "ConeShadows: " << this->ConeShadows << "\n";
  os << indent << "ShadowConeAperture: " << this->ShadowConeAperture << "\n";
  os << indent << "GIActive: " << this->GIActive << "\n";
  const Internals& in = *this->Internal;
  os << indent << "Grid: " << in.Grid.Resolution << "^3 voxels of " << in.Grid.VoxelSize
     << " from (" << in.Grid.Origin.x << ", " << in.Grid.Origin.y << ", " << in.Grid.Origin.z
     << ")\n";
  os << indent << "VoxelMemoryBytes: " << this->GetVoxelMemoryBytes() << "\n";
  for (int stage = 0; stage < NUMBER_OF_STAGES; ++stage)
  {
    os << indent << "Stage " << GetStageName(stage) << ": "
       << (in.Ran[stage] ? "ran" : "skipped");
    if (in.Ran[stage] && this->TimeStages)
    {
      os << ", " << in.Times[stage] << " ms";
    }
    os << "\n";
  }
}
