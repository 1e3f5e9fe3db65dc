/**
 * Voxelize stage: the voxel volumes and the internal render pass that fills them.
 *
 * Actors whose triangles compute voxelization can read (plain polydata surfaces: VoxelizeCompute)
 * are voxelized from their GPU-resident copies; the others are rendered by copies of their VTK mappers (MapperCopies: the user's mappers never
 * switch shader code), with this pass in their render-pass keys so that it injects its code (voxelize.geom, voxelize.frag): every fragment adds its
 * unlit colour, geometric normal and emission to exact integer accumulators (one shader
 * storage buffer per channel; with translucent actors in the scene, one more summing the
 * fragments' quantized 1 - opacity), seen through an orthographic camera fitted to the grid
 * cube.
 * A flag volume marks voxels written by static actors: dynamic actors skip them, and the
 * clear (clear_dynamic.comp) keeps them. The resolve (voxel_resolve.comp) turns the sums into
 * the sampled volumes: albedo and normal RGBA8, emission RGBA16F; and lists the occupied
 * bricks, which the later per-voxel stages work on. Where no surface is, it takes the
 * renderer's volumes (VolumeVoxels) with their partial occupancy and no normal.
 */
#ifndef VoxelGIVoxelizePass_h
#define VoxelGIVoxelizePass_h

#include "GLHelpers.h"
#include "MapperCopies.h"
#include "VolumeVoxels.h"
#include "VoxelizeCompute.h"
#include "shader_interface.h"

#include "vtkNew.h"              // for vtkNew
#include "ViewRenderer.h"         // for ViewRenderer
#include "vtkOpenGLRenderPass.h" // for the superclass

#include <array>
#include <string>
#include <unordered_map>
#include <vector>

class vtkActor;
class vtkCamera;
class vtkProp;

namespace voxelgi
{
struct Frame;

class VoxelizePass : public vtkOpenGLRenderPass
{
public:
  static VoxelizePass* New();
  vtkTypeMacro(VoxelizePass, vtkOpenGLRenderPass);

  /// Allocate the volumes and build the programs for the frame's grid and emission. Returns
  /// false with a message (naming the memory it needed) when it cannot.
  bool Prepare(const Frame& frame, std::string& error);
  /// Clear, render the frame's actors (the static ones only for a full update), resolve.
  void Run(const Frame& frame);
  /// Render the state's props into the accumulators (Run sets up the view renderer, whose
  /// camera is the grid's, and the GL state).
  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /// Bytes one resolution needs, for messages and for limits checks before allocating.
  static std::size_t RequiredBytes(int resolution, bool emission, bool translucent);

  int GetResolution() const { return this->Resolution; }
  bool HasEmission() const { return this->Emission; }
  /// Whether voxels of partial occupancy may be present (translucent surfaces, volumes).
  bool HasMedia() const { return this->Translucent || this->Volumes.GetGrid() != nullptr; }
  bool GetHardwareConservative() const { return this->HardwareConservative; }
  std::size_t MemoryBytes() const;
  /// The part of MemoryBytes() that only emissive scenes need.
  std::size_t EmissionBytes() const;
  /// `actor`'s GPU-resident triangles, brought up to date, where the frame's settings let
  /// compute voxelization read it; null when its mapper has to draw it (context current).
  const SceneBuffers::Entry* Resident(const Frame& frame, vtkActor* actor);
  /// The actors' triangles kept for compute voxelization and the volumes' voxels and
  /// textures (not in MemoryBytes(): they follow the scene, not the settings).
  std::size_t SceneBytes() const
  {
    return this->Compute.MemoryBytes() + this->Volumes.MemoryBytes();
  }

  /// The sampled volumes (emission only in emissive scenes).
  const Volume3D& GetAlbedo() const { return this->AlbedoVolume; }
  const Volume3D& GetNormal() const { return this->NormalVolume; }
  const Volume3D& GetEmission() const { return this->EmissionVolume; }
  /// The occupied bricks (brick_list.glsl), listed by the resolve: the bounce dispatches
  /// over it.
  const StorageBuffer& GetBrickList() const { return this->BrickList; }
  /// Read back: counts (one uint per voxel) and flags (one byte).
  void ReadCounts(std::vector<unsigned int>& counts) const;
  void ReadFlags(std::vector<unsigned char>& flags) const;

  // Shader injection into the mappers (see vtkOpenGLRenderPass).
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override { return this->ShaderStageTime.GetMTime(); }

protected:
  VoxelizePass();
  ~VoxelizePass() override;

private:
  VoxelizePass(const VoxelizePass&) = delete;
  void operator=(const VoxelizePass&) = delete;

  std::string Defines() const;
  /// Allocate the accumulators (`channelBytes` each) and volumes of the current resolution
  /// and variant, releasing those it does not use; false when GL could not.
  bool Allocate(std::size_t channelBytes);
  /// Build the resolve for the frame's variant (emission, volumes).
  bool PrepareResolve(std::string& error);
  /// Aim the voxelization camera: its view volume is the grid cube.
  void AimCamera(const Frame& frame);
  /// Render `props` through their mappers and voxelize `items` by compute into the
  /// accumulators, as static or dynamic actors.
  void Draw(const Frame& frame, std::vector<vtkProp*>& props,
    const std::vector<VoxelizeCompute::Item>& items, bool staticPass);
  /// Put every brick of the grid in the brick list.
  void ListEveryBrick();
  void Clear(const Frame& frame);
  void Resolve(const Frame& frame);
  void BindAccumulators() const;
  /// Distributed: every rank takes the union of the ranks' static flags (before the dynamic
  /// actors draw, which skip static voxels).
  void MergeFlags(const Frame& frame);
  /// Distributed: every rank takes the sums of all ranks' accumulators. After a dynamic
  /// update the static voxels hold the merged sums already: only the first rank adds them.
  void MergeSums(const Frame& frame);

  int Resolution = 0;
  bool Emission = false;
  bool Translucent = false; // the variant that voxelizes translucent surfaces
  bool HardwareConservative = false;
  bool StaticPass = false;
  std::unordered_map<vtkProp*, std::array<double, 3>> PropEmissions;
  std::array<StorageBuffer, VOXELGI_BASE_CHANNELS + VOXELGI_EMISSION_CHANNELS + 1> Accumulators;
  StorageBuffer BrickList;
  Volume3D FlagVolume;
  Volume3D AlbedoVolume;
  Volume3D NormalVolume;
  Volume3D EmissionVolume;
  GLProgram ClearProgram;
  GLProgram ResolveProgram;
  EmptyFramebuffer Framebuffer;
  ViewRenderer View; // draws through the grid camera
  MapperCopies Copies; // draw the actors with this pass's shader code only
  VoxelizeCompute Compute; // the actors read into buffers
  VolumeVoxels Volumes;    // the volumes, merged by the resolve
  vtkTimeStamp ShaderStageTime;
};

}

#endif
