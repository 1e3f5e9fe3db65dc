/**
 * Scan stage (CPU, GL-free, every frame): collects the renderer's voxelized props, compares
 * their modification times with the frame the voxels were built from, applies the update
 * policy and fits the voxel grid. It decides what the Voxelize stage does ("leave out what
 * the scene does not need"): nothing, the dynamic actors alone, or everything. It also keys
 * what an image shows, so that a frame in which nothing changed presents the last one again.
 *
 * Unit tested without a GL context (Testing/Unit/TestSceneScan.cxx).
 */
#ifndef VoxelGISceneScan_h
#define VoxelGISceneScan_h

#include "ImageSliceProxies.h"
#include "ImposterProxies.h"
#include "PropKeys.h"
#include "PropReader.h"
#include "VolumeVoxels.h"
#include "VoxelGrid.h"

#include "vtkType.h"         // for vtkMTimeType
#include "vtkWeakPointer.h"  // for vtkWeakPointer

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

class vtkActor;
class vtkProp;
class vtkRenderer;

namespace voxelgi
{
class Ranks;
struct Settings;

/// What the scan remembers of a voxelized actor between frames.
struct ActorRecord
{
  vtkWeakPointer<vtkActor> Actor;
  vtkMTimeType Signature = 0; // latest modification time of actor, mapper and input
  vtkMTimeType InputTime = 0; // the input's: its points were checked for NaN at this time
  std::array<double, 3> Emission{ { 0.0, 0.0, 0.0 } };
  bool UserDynamic = false;
  bool Dynamic = false; // user choice, or changed after voxelization (AutoDynamic)
  // Which scan last saw its data, mapper or actor change (a new one where the scan cannot
  // tell): stages that keep results per actor compare it (ShadowMaps).
  std::uint64_t Revision = 0;
  // Translucent (VTK draws it in its translucent step): it casts shadows that pass part of
  // the light (ShadowTransmittance) and is voxelized with partial occupancy.
  bool Translucent = false;
};

/// What the scan has to tell the user; the pass reports it.
struct ScanMessages
{
  std::vector<std::string> Warnings;
  std::string Error;
};

/// What the Voxelize stage has to do this frame.
struct VoxelUpdate
{
  bool Run = false;     // rebuild any voxels at all
  bool Full = false;    // all of them (else the dynamic actors only)
  bool Emission = false; // the scene has emissive props
  bool Translucent = false; // the scene has translucent actors (partial occupancy)
  bool Volumes = false;  // the scene has volumes to resample (VolumeVoxels)
  VoxelGrid Grid;       // the grid to voxelize into
};

class SceneScan
{
public:
  /// Scan `renderer` with `settings` (HardwareConservativeRaster: on and available). Returns
  /// false when there is nothing to voxelize or no grid fits the scene (then `messages` has
  /// the error): GI cannot run this frame. `update` says what to rebuild. Distributed
  /// `ranks` agree on one grid around all their pieces and on one update (a collective
  /// call); a rank without a piece then voxelizes nothing and still takes part. `inRender`:
  /// the scan runs inside the renderer's Render(), after VTK's culler read the props' bounds
  /// (PropReader), not ahead of it.
  bool Scan(vtkRenderer* renderer, const Settings& settings, Ranks& ranks, VoxelUpdate& update,
    ScanMessages& messages, bool inRender = false);
  /// The voxels were rebuilt as `update` said: remember what they were built from.
  void Accept(const VoxelUpdate& update, const Settings& settings);
  /// The voxels are gone (released, or could not be built): the next scan rebuilds all.
  void Reset();
  /// Force a full rebuild at the next scan, whatever the update policy.
  void Invalidate() { this->InvalidateRequested = true; }
  /// Re-read the signatures of the actors after a frame that voxelized: changes VTK made
  /// while rendering (a mapper creating its default lookup table) are not news.
  void RefreshSignatures();

  /// The grid of the current voxels (invalid before the first voxelization).
  const VoxelGrid& GetGrid() const { return this->BuiltGrid; }
  /// The actors the voxels were built from, in scene order.
  const std::vector<ActorRecord>& GetRecords() const { return this->Records; }
  /// The volumes resampled into the voxels (VolumeVoxels), in scene order.
  const std::vector<VolumeRecord>& GetVolumes() const { return this->Volumes; }
  /// Any voxelized actor with a specular coefficient above 0 (else no specular cone).
  bool GetAnySpecular() const { return this->AnySpecular; }
  /// CPU time of the last Scan(), milliseconds.
  double GetMilliseconds() const { return this->Milliseconds; }

  /// What the renderer's image shows: renderer, camera, viewport, props, lights and the
  /// pass's settings (as `settingsTime`); equal keys, equal images. `scanned`: the props'
  /// signatures as this frame's Scan() read them (the voxelization in between changes what
  /// VTK draws, not what the image is made from); else as VTK drew them (what it modified
  /// while drawing, such as a mapper's default lookup table, is not a change). Props are read
  /// in full when the frame has not scanned them (a pass that follows a voxel source).
  std::vector<unsigned long long> ImageKey(
    vtkRenderer* renderer, vtkMTimeType settingsTime, bool scanned) const;

private:
  /// Collect the visible opaque surface actors and the volumes (none in a `distributed`
  /// render: a rank would resample its piece alone); false when there is neither.
  bool Collect(vtkRenderer* renderer, bool inRender, bool distributed,
    std::vector<ActorRecord>& records, std::vector<VolumeRecord>& volumes, double bounds[6],
    std::vector<std::string>& warnings);
  /// The actor voxelized for `prop` (with `bounds` and `signature` as read): the prop, or the
  /// proxy that stands in for an image slice or for points drawn as spheres (then the proxy's
  /// bounds, and the signature raised to its last rebuild); null with `why` when that proxy
  /// cannot be made. Props with proxies go into `proxied`.
  vtkActor* StandIn(vtkProp* prop, vtkRenderer* renderer, const double*& bounds,
    vtkMTimeType& signature, std::string& why, std::set<vtkProp*>& proxied);
  /// Warn once about each new kind of prop left to VTK (`leftOut`: reason -> count).
  void ReportLeftOut(const std::map<std::string, int>& leftOut, std::vector<std::string>& warnings);
  /// Compare with the accepted records: full rebuild, dynamic change, or nothing; give each
  /// record its revision.
  void Compare(
    std::vector<ActorRecord>& records, const Settings& settings, bool& full, bool& dynamic);
  /// Update policy: is a pending change rebuilt this frame?
  bool Due(const Settings& settings, bool settingsChanged, bool pending);

  ImageSliceProxies Slices; // image slices as textured quads
  ImposterProxies Imposters; // points drawn as spheres, as glyphed spheres
  PropReader Reader;        // what was read of each view prop, kept between frames
  std::vector<ActorRecord> Records;
  std::vector<ActorRecord> Pending; // scanned, waiting for Accept()
  std::vector<VolumeRecord> Volumes;
  std::vector<VolumeRecord> PendingVolumes;
  bool Voxelized = false;
  VoxelGrid BuiltGrid;
  double BuiltPadding = -1.0;
  bool BuiltEmission = false;
  bool BuiltTranslucent = false;
  bool BuiltHardware = false;
  bool BuiltCompute = false;
  std::uint64_t Revisions = 0; // the last ActorRecord::Revision given
  bool InvalidateRequested = false;
  int FramesSinceUpdate = 0;
  bool AnySpecular = false;
  std::map<std::string, int> WarnedLeftOut; // kinds of props left out: the count said
  double Milliseconds = 0.0;
  std::vector<vtkMTimeType> PropSignatures; // of every view prop, by the last Scan()
};

}

#endif
