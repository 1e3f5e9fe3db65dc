#include "SceneScan.h"

#include "Frame.h"
#include "Ranks.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkImageSlice.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <map>
#include <set>
#include <unordered_map>

namespace voxelgi
{

namespace
{
/// The points of an actor's polydata input, or of every polydata block of a composite input.
std::vector<vtkPoints*> PointSets(vtkActor* actor)
{
  std::vector<vtkPoints*> pointSets;
  vtkDataObject* input = actor->GetMapper()->GetInputDataObject(0, 0);
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (auto* block = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
      {
        pointSets.push_back(block->GetPoints());
      }
    }
  }
  else if (auto* poly = vtkPolyData::SafeDownCast(input))
  {
    pointSets.push_back(poly->GetPoints());
  }
  return pointSets;
}

/// Warning for an actor whose input has NaN or Inf point coordinates, or empty.
std::string NonFinitePoints(vtkActor* actor)
{
  vtkIdType bad = 0, total = 0;
  double p[3];
  for (vtkPoints* points : PointSets(actor))
  {
    for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
    {
      points->GetPoint(i, p);
      bad += (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) ? 0 : 1;
    }
    total += points ? points->GetNumberOfPoints() : 0;
  }
  if (bad == 0)
  {
    return std::string();
  }
  std::ostringstream text;
  text << "An actor has " << bad << " of " << total
       << " points with NaN or Inf coordinates; its triangles that use them are not voxelized.";
  return text.str();
}

void Merge(double bounds[6], const double* b, bool first)
{
  for (int i = 0; i < 3; ++i)
  {
    bounds[2 * i] = first ? b[2 * i] : std::min(bounds[2 * i], b[2 * i]);
    bounds[2 * i + 1] = first ? b[2 * i + 1] : std::max(bounds[2 * i + 1], b[2 * i + 1]);
  }
}

/// World bounds of the finite coordinates of an actor's points: VTK's bounds of an input
/// with one Inf point are infinite, and the actor's other triangles still belong in the
/// grid. False when it has no finite point.
bool FiniteBounds(vtkActor* actor, double bounds[6])
{
  double local[6];
  bool any = false;
  for (vtkPoints* points : PointSets(actor))
  {
    double b[6];
    for (int c = 0; points && c < 3; ++c)
    {
      points->GetData()->GetFiniteRange(b + 2 * c, c);
    }
    if (points && b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5])
    {
      Merge(local, b, !any);
      any = true;
    }
  }
  for (int corner = 0; any && corner < 8; ++corner)
  {
    double p[4] = { local[corner & 1], local[2 + ((corner >> 1) & 1)],
      local[4 + ((corner >> 2) & 1)], 1.0 };
    actor->GetMatrix()->MultiplyPoint(p, p);
    const double world[6] = { p[0] / p[3], p[0] / p[3], p[1] / p[3], p[1] / p[3], p[2] / p[3],
      p[2] / p[3] };
    Merge(bounds, world, corner == 0);
  }
  return any && std::all_of(bounds, bounds + 6, [](double v) { return std::isfinite(v); });
}

/// A prop's usable bounds: `bounds` when finite, else those of its finite points (written to
/// `finite`), else null (nothing finite to place in the grid).
const double* UsableBounds(vtkProp* prop, const double* bounds, double finite[6])
{
  if (std::all_of(bounds, bounds + 6, [](double v) { return std::isfinite(v); }))
  {
    return bounds;
  }
  auto* actor = vtkActor::SafeDownCast(prop);
  return actor && actor->GetMapper() && FiniteBounds(actor, finite) ? finite : nullptr;
}
}

//------------------------------------------------------------------------------
namespace
{
/// The record of `actor`, drawn for `prop` (the prop itself, or an image slice's proxy), whose
/// record in the last scan was `previous` (null: new). A new or changed input is checked for
/// non-finite points once.
ActorRecord MakeRecord(vtkProp* prop, vtkActor* actor, vtkMTimeType signature,
  vtkMTimeType inputTime, const ActorRecord* previous, std::vector<std::string>& warnings)
{
  ActorRecord record;
  record.Actor = actor;
  record.Signature = signature;
  record.InputTime = inputTime;
  if (!previous || inputTime != previous->InputTime)
  {
    std::string bad = NonFinitePoints(actor);
    if (!bad.empty())
    {
      warnings.push_back(bad);
    }
  }
  // The user's keys are on the prop (a slice's, not its proxy's).
  record.Emission = PropEmission(prop);
  record.UserDynamic = PropDynamic(prop);
  record.Dynamic = record.UserDynamic || (previous && previous->Dynamic);
  return record;
}
}

namespace
{
/// An actor's last record: scenes keep their order from frame to frame, so it is looked for
/// at the actor's position first, and in an index of the records only when it moved.
class PreviousRecords
{
public:
  explicit PreviousRecords(const std::vector<ActorRecord>& records)
    : Records(records)
  {
  }
  /// The last record of `actor`, now the `at`-th (null: new).
  const ActorRecord* Find(vtkActor* actor, std::size_t at)
  {
    if (at < this->Records.size() && this->Records[at].Actor == actor)
    {
      return &this->Records[at];
    }
    if (this->Index.empty())
    {
      for (const ActorRecord& record : this->Records)
      {
        this->Index[record.Actor] = &record;
      }
    }
    const auto found = this->Index.find(actor);
    return found != this->Index.end() ? found->second : nullptr;
  }

private:
  const std::vector<ActorRecord>& Records;
  std::unordered_map<vtkActor*, const ActorRecord*> Index;
};
}

bool SceneScan::Collect(vtkRenderer* renderer, bool inRender, bool distributed,
  std::vector<ActorRecord>& records, std::vector<VolumeRecord>& volumes, double bounds[6],
  std::vector<std::string>& warnings)
{
  // Every visible opaque surface actor drawn by a polydata mapper, including the ones outside
  // the view frustum (they still cast and reflect light).
  PreviousRecords previous(this->Records);
  vtkMath::UninitializeBounds(bounds);
  std::map<std::string, int> leftOut; // visible 3D props VTK renders without GI, by reason
  std::set<vtkProp*> proxied;         // image slices and point sprites voxelized as proxies
  bool anySpecular = false;
  vtkPropCollection* props = renderer->GetViewProps();
  this->PropSignatures.clear();
  this->Reader.Begin(renderer, inRender);
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    const PropReading& reading = this->Reader.Read(prop);
    const vtkMTimeType signature = reading.Signature;
    this->PropSignatures.push_back(signature);
    if (!reading.HasBounds)
    {
      continue;
    }
    const double* b = reading.Bounds;
    if (!reading.LeftOut.empty())
    {
      // 2D props (text, legends, scalar bars) have no bounds and never get here.
      ++leftOut[reading.LeftOut];
      continue;
    }
    double finite[6];
    b = UsableBounds(prop, b, finite);
    if (!b)
    {
      ++leftOut["non-finite bounds (no finite point)"];
      continue;
    }
    if (auto* volume = vtkVolume::SafeDownCast(prop))
    {
      if (distributed)
      {
        ++leftOut["vtkVolume (volumes in a distributed render)"];
        continue;
      }
      volumes.push_back({ volume, signature });
      Merge(bounds, b, records.empty() && volumes.size() == 1);
      continue;
    }
    std::string why;
    vtkMTimeType recordSignature = signature;
    vtkActor* actor = this->StandIn(prop, renderer, b, recordSignature, why, proxied);
    if (!actor)
    {
      ++leftOut[why];
      continue;
    }
    records.push_back(MakeRecord(
      prop, actor, recordSignature, reading.InputTime, previous.Find(actor, records.size()),
      warnings));
    records.back().Translucent = reading.Translucent;
    Merge(bounds, b, records.size() == 1 && volumes.empty());
    anySpecular = anySpecular || actor->GetProperty()->GetSpecular() > 0.0;
  }
  this->Reader.End();
  this->Slices.Retain(proxied);
  this->Imposters.Retain(proxied);
  this->ReportLeftOut(leftOut, warnings);
  this->AnySpecular = anySpecular;
  return !records.empty() || !volumes.empty();
}

vtkActor* SceneScan::StandIn(vtkProp* prop, vtkRenderer* renderer, const double*& bounds,
  vtkMTimeType& signature, std::string& why, std::set<vtkProp*>& proxied)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  // An image slice is voxelized through its proxy: a textured quad.
  if (auto* slice = vtkImageSlice::SafeDownCast(prop))
  {
    proxied.insert(prop);
    return this->Slices.Update(slice, signature, why);
  }
  if (!actor || !ImposterProxies::Applies(actor))
  {
    return actor;
  }
  proxied.insert(prop);
  vtkActor* proxy = this->Imposters.Update(actor, signature, renderer, why);
  if (proxy)
  {
    bounds = proxy->GetBounds(); // the spheres, not only their centres
    signature = std::max(signature, proxy->GetMTime()); // a zoom rebuilds the proxy
  }
  return proxy;
}

void SceneScan::ReportLeftOut(
  const std::map<std::string, int>& leftOut, std::vector<std::string>& warnings)
{
  // Said for each new kind of prop left out, and again with the count once that has
  // doubled (props often arrive after the first render), not at every prop added.
  std::ostringstream text;
  for (const auto& kind : leftOut)
  {
    int& said = this->WarnedLeftOut[kind.first];
    if (said == 0 || kind.second >= 2 * said)
    {
      said = kind.second;
      text << (text.tellp() > 0 ? "; " : "") << kind.second << " x " << kind.first;
    }
  }
  if (text.tellp() > 0)
  {
    warnings.push_back("Rendered by VTK without voxel GI: " + text.str() + ".");
  }
}

//------------------------------------------------------------------------------
void SceneScan::Compare(
  std::vector<ActorRecord>& records, const Settings& settings, bool& full, bool& dynamic)
{
  full = !this->Voxelized || records.size() != this->Records.size();
  dynamic = false;
  const bool unmatched = full;
  // Every record is compared, also after one has asked for a full rebuild: all the actors
  // that changed become dynamic in that one rebuild.
  for (std::size_t i = 0; !unmatched && i < records.size(); ++i)
  {
    ActorRecord& record = records[i];
    const ActorRecord& old = this->Records[i];
    if (old.Actor.GetPointer() != record.Actor.GetPointer())
    {
      full = true;
      break;
    }
    const bool changed = record.Signature > old.Signature || record.Emission != old.Emission;
    record.Revision = changed ? 0 : old.Revision;
    if (record.UserDynamic != old.UserDynamic)
    {
      full = true; // the static/dynamic split itself changed
    }
    else if (changed && record.Dynamic)
    {
      dynamic = true;
    }
    else if (changed)
    {
      full = true;
      record.Dynamic = settings.AutoDynamic;
    }
  }
  // A new revision where the data changed or the scan cannot tell (0); Invalidate() and
  // updates every frame stand for changes the scan cannot see.
  const bool unseen = this->InvalidateRequested || settings.UpdatePolicy == UPDATE_EVERY_FRAME;
  for (ActorRecord& record : records)
  {
    record.Revision = record.Revision && !unseen ? record.Revision : ++this->Revisions;
  }
}

//------------------------------------------------------------------------------
bool SceneScan::Due(const Settings& settings, bool settingsChanged, bool pending)
{
  // Changes of the voxel settings (and the first frame) always rebuild; changes of the scene
  // follow the update policy.
  const bool forced = settingsChanged || this->InvalidateRequested;
  switch (settings.UpdatePolicy)
  {
    case UPDATE_EVERY_FRAME:
      return true;
    case UPDATE_EVERY_N_FRAMES:
      return forced || (pending && this->FramesSinceUpdate + 1 >= settings.UpdateInterval);
    case UPDATE_ON_DEMAND:
      return forced;
    default:
      return forced || pending;
  }
}

//------------------------------------------------------------------------------
namespace
{
/// What a scan found that the ranks of a distributed render must agree on.
struct Findings
{
  double Bounds[6] = {};
  bool Collected = false;
  bool Full = false;
  bool Dynamic = false;
  bool Emission = false;
  bool Translucent = false;
  bool SettingsChanged = false;
  bool Invalidate = false;
};

/// Writes the milliseconds since its construction to `Result` when it goes out of scope.
struct StopWatch
{
  std::chrono::steady_clock::time_point Start;
  double& Result;
  ~StopWatch()
  {
    this->Result =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - this->Start)
        .count();
  }
};
}

bool SceneScan::Scan(vtkRenderer* renderer, const Settings& settings, Ranks& ranks,
  VoxelUpdate& update, ScanMessages& messages, bool inRender)
{
  const StopWatch watch{ std::chrono::steady_clock::now(), this->Milliseconds };

  update = VoxelUpdate();
  std::vector<ActorRecord> records;
  std::vector<VolumeRecord> volumes;
  Findings found;
  found.Collected = this->Collect(
    renderer, inRender, ranks.Distributed(), records, volumes, found.Bounds, messages.Warnings);
  this->Compare(records, settings, found.Full, found.Dynamic);
  // A volume that changed is resampled and merged again by the resolve: the actors' voxels
  // stay.
  found.Dynamic = found.Dynamic || volumes != this->Volumes;
  for (const ActorRecord& record : records)
  {
    found.Emission = found.Emission || Emits(record.Emission);
    found.Translucent = found.Translucent || record.Translucent;
  }
  found.SettingsChanged = !this->Voxelized || !this->BuiltGrid.IsValid() ||
    this->BuiltGrid.Resolution != settings.VoxelResolution ||
    this->BuiltPadding != settings.GridPadding ||
    settings.HardwareConservativeRaster != this->BuiltHardware ||
    settings.ComputeVoxelization != this->BuiltCompute;
  found.Invalidate = this->InvalidateRequested;
  // Distributed: one grid around every rank's piece, and what any rank must rebuild, all
  // rebuild.
  ranks.Union(found.Bounds, { &found.Collected, &found.Full, &found.Dynamic, &found.Emission,
                              &found.Translucent, &found.SettingsChanged, &found.Invalidate });
  this->InvalidateRequested = found.Invalidate;
  if (!found.Collected)
  {
    this->Records.clear();
    this->Volumes.clear();
    return false;
  }
  const double* bounds = found.Bounds;
  const bool settingsChanged = found.SettingsChanged || found.Emission != this->BuiltEmission ||
    found.Translucent != this->BuiltTranslucent;
  // The scene left the grid or shrank to under half of it.
  const double extent =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  const bool refit = settingsChanged || !this->BuiltGrid.Covers(bounds) ||
    extent * (1.0 + 2.0 * settings.GridPadding) < 0.5 * this->BuiltGrid.Size();
  if (!this->Due(settings, settingsChanged, found.Full || found.Dynamic || refit))
  {
    // Keep the voxels and the records they were built from: the change stays pending.
    ++this->FramesSinceUpdate;
    return true;
  }
  update.Full = found.Full || refit || this->InvalidateRequested ||
    settings.UpdatePolicy == UPDATE_EVERY_FRAME;
  this->InvalidateRequested = false;
  this->FramesSinceUpdate = 0;
  update.Grid = this->BuiltGrid;
  update.Grid.SetScene(bounds);
  if (refit &&
    FitVoxelGrid(bounds, settings.VoxelResolution, settings.GridPadding, update.Grid) !=
      FitStatus::Ok)
  {
    messages.Error = "Could not fit a voxel grid around the scene bounds; rendering without GI.";
    this->Records.clear();
    this->Volumes.clear();
    return false;
  }
  update.Run = true;
  update.Emission = found.Emission;
  update.Translucent = found.Translucent;
  update.Volumes = !volumes.empty();
  this->Pending = std::move(records);
  this->PendingVolumes = std::move(volumes);
  return true;
}

//------------------------------------------------------------------------------
void SceneScan::Accept(const VoxelUpdate& update, const Settings& settings)
{
  this->Records = std::move(this->Pending);
  this->Pending.clear();
  this->Volumes = std::move(this->PendingVolumes);
  this->PendingVolumes.clear();
  this->BuiltGrid = update.Grid;
  this->BuiltPadding = settings.GridPadding;
  this->BuiltEmission = update.Emission;
  this->BuiltTranslucent = update.Translucent;
  this->BuiltHardware = settings.HardwareConservativeRaster;
  this->BuiltCompute = settings.ComputeVoxelization;
  this->Voxelized = true;
}

void SceneScan::Reset()
{
  this->Records.clear();
  this->Pending.clear();
  this->Volumes.clear();
  this->PendingVolumes.clear();
  this->Voxelized = false;
  this->BuiltGrid = VoxelGrid();
  this->PropSignatures.clear();
}

void SceneScan::RefreshSignatures()
{
  for (ActorRecord& record : this->Records)
  {
    if (record.Actor)
    {
      record.Signature = PropReader::ActorSignature(record.Actor);
    }
  }
}

//------------------------------------------------------------------------------
std::vector<unsigned long long> SceneScan::ImageKey(
  vtkRenderer* renderer, vtkMTimeType settingsTime, bool scanned) const
{
  const std::vector<vtkMTimeType>* signatures = &this->PropSignatures;
  std::vector<unsigned long long> key{ renderer->GetMTime(), settingsTime,
    renderer->GetActiveCamera()->GetMTime() };
  int size[4];
  renderer->GetTiledSizeAndOrigin(size, size + 1, size + 2, size + 3);
  key.insert(key.end(), size, size + 4);
  // The G-buffer takes a pixel's surface at one of its samples (GBufferPass).
  vtkRenderWindow* window = renderer->GetRenderWindow();
  key.push_back(static_cast<unsigned long long>(window ? window->GetMultiSamples() : 0));
  if (signatures && static_cast<int>(signatures->size()) != renderer->GetViewProps()->GetNumberOfItems())
  {
    signatures = nullptr;
  }
  vtkCollectionSimpleIterator it;
  renderer->GetViewProps()->InitTraversal(it);
  std::size_t i = 0;
  while (vtkProp* prop = renderer->GetViewProps()->GetNextProp(it))
  {
    if (!signatures)
    {
      key.push_back(PropReader::PropSignature(prop));
    }
    else
    {
      const vtkMTimeType signature = (*signatures)[i++];
      key.push_back(scanned ? signature : PropReader::DrawnSignature(prop, signature));
    }
    key.push_back(prop->GetVisibility());
  }
  // Every light VTK shades with (the light block holds the first 16 only).
  vtkCollectionSimpleIterator lit;
  renderer->GetLights()->InitTraversal(lit);
  while (vtkLight* light = renderer->GetLights()->GetNextLight(lit))
  {
    key.push_back(light->GetMTime());
  }
  return key;
}


}
