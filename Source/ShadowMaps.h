/**
 * ShadowMaps stage (shadow_maps.glsl reads them): a depth map per directional or spot light
 * and six (a cube) per point light, rendered from the light with the voxelized actors as
 * casters (their GPU-resident triangles where compute voxelization reads them: ShadowDepth;
 * the others through copies of their mappers), and beside them the light that translucent
 * actors let through (ShadowTransmittance); a layer whose view and casters did not change
 * since it was drawn is kept. Also the matrices from grid coordinates to each map's clip space, in
 * the `VoxelShadowBlock` uniform block (Shaders/shadow_block.h). The voxel lighting and the
 * pixels' shadows (ConeTrace) look them up. Headlights have none: their shadows are hidden
 * behind what casts them.
 */
#ifndef VoxelGIShadowMaps_h
#define VoxelGIShadowMaps_h

#include "Frame.h" // for ScopedStage
#include "GLHelpers.h"
#include "MapperCopies.h"
#include "ShadowDepth.h"
#include "ShadowTransmittance.h"
#include "ViewRenderer.h" // for ViewRenderer
#include "shader_interface.h"
#include "shadow_block.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

class vtkActor;
class vtkLight;
class vtkMatrix4x4;
class vtkRenderer;
class vtkWindow;

namespace voxelgi
{
struct Frame;
class LightBlock;
class VoxelizePass;

class ShadowMaps
{
public:
  /// `voxels` keeps the actors' GPU-resident triangles.
  explicit ShadowMaps(VoxelizePass& voxels)
    : Voxels(voxels)
  {
  }

  static constexpr int MaxLights = VOXELGI_MAX_LIGHTS;
  static constexpr int MaxLayers = VOXELGI_MAX_SHADOW_LAYERS;

  /// Choose the lights that get maps (block order) and allocate the maps at the frame's
  /// ShadowMapResolution, or smaller where that does not fit (`note` says so, once per
  /// resolution and map count); where no size fits, the lights raymarch the voxels. False
  /// (with `error`) only when the maps' small uniform buffer cannot be allocated.
  bool Prepare(const Frame& frame, std::string& error, std::string& note);
  /// What the maps of `lights` take at `size` texels per side.
  static std::size_t RequiredBytes(int size, const std::vector<vtkLight*>& lights);
  /// Render the maps with the frame's voxelized actors as casters; upload the block.
  void Run(const Frame& frame);
  /// Whether any light has a map.
  bool HasMaps() const { return this->Maps.Layers() > 0; }
  /// GPU memory of the maps and their transmittance.
  std::size_t Bytes() const { return this->Maps.Bytes() + this->Transmittance.Bytes(); }
  /// Bind the block at VOXELGI_SHADOW_BLOCK_BINDING and the maps to `program`'s (in use)
  /// `shadowMaps` sampler.
  void Bind(GLProgram& program, SamplerBindings& samplers) const;

  ShadowMapArray Maps;
  void ReleaseGraphicsResources(vtkWindow* window)
  {
    this->Wanted[0] = this->Wanted[1] = this->Granted = 0;
    this->Maps.Release();
    this->Drawn.clear();
    this->Buffer.Release();
    this->Copies.ReleaseGraphicsResources(window);
    this->Depth.ReleaseGraphicsResources();
    this->Transmittance.ReleaseGraphicsResources();
    this->View.Release();
  }

private:
  /// shadow_block.h's VoxelShadowBlock, the one declaration C++ and GLSL share.
  using Block = glsl::VoxelShadowBlock;
  // std140: mat4 64 bytes, ivec4 and vec4 16, arrays of them without gaps
  static_assert(offsetof(Block, shadowLights) == 64 * MaxLayers &&
      offsetof(Block, shadowTexels) == 64 * MaxLayers + 16 * MaxLights &&
      offsetof(Block, shadowInfo) == 64 * MaxLayers + 32 * MaxLights &&
      sizeof(Block) == 64 * MaxLayers + 32 * MaxLights + 16,
    "not std140");

  /// Allocate `layers` maps of `size` or, where they do not fit, the largest halving down to
  /// MinSize (0: none fits); decided again only when the size or count asked for changes.
  bool Allot(int size, int layers, std::string& note);
  static constexpr int MinSize = 128;
  int Wanted[2] = { 0, 0 }; // the size and count last asked for
  int Granted = 0;          // the size allocated for them

  /// A voxelized actor as the layers see it, read once per Run: the key part (identity,
  /// the scan's revision of its data: ActorRecord::Revision, and its matrix, row-major,
  /// since a follower's turns with the camera without a change to its data) and what
  /// drawing takes.
  struct Caster
  {
    vtkActor* Actor;
    std::uint64_t Revision;
    std::array<double, 16> Matrix;
    std::array<double, 6> Bounds;
    const SceneBuffers::Entry* Buffers; // null: drawn through a copy of its mapper
    bool Translucent;                   // drawn into the layer's transmittance
    bool operator==(const Caster& other) const
    {
      return this->Actor == other.Actor && this->Revision == other.Revision &&
        this->Matrix == other.Matrix;
    }
  };
  /// What a layer was drawn from: its view (clip from world, row-major) and its casters.
  struct LayerKey
  {
    std::array<double, 16> ClipFromWorld{};
    std::vector<Caster> Casters;
    bool operator==(const LayerKey& other) const
    {
      return this->ClipFromWorld == other.ClipFromWorld && this->Casters == other.Casters;
    }
  };
  /// The frame's voxelized actors as casters (this->Casters).
  void ReadCasters(const Frame& frame);
  /// Allocate the transmittance layers while any actor of the frame is translucent (else
  /// free them); layers drawn without them are drawn again. Where they do not fit, `note`
  /// says so and translucent actors cast no shadow.
  void PrepareTransmittance(const Frame& frame, std::string& note);
  /// Draw the casters of `key` into the bound layer: opaque depth, then transmittance.
  void DrawCasters(const Frame& frame, int layer, const LayerKey& key, vtkRenderer* renderer);
  /// Draw `layer` from `clipFromWorld` unless it holds that view of the same casters; the
  /// first layer drawn starts the stage's clock.
  void DrawLayer(const Frame& frame, int layer, vtkMatrix4x4* clipFromWorld,
    vtkRenderer* renderer, std::optional<ScopedStage>& stage);

  VoxelizePass& Voxels;
  ViewRenderer View; // draws through each light's camera
  MapperCopies Copies; // depth-only draws never switch the user's mappers
  ShadowDepth Depth;   // the actors with GPU-resident triangles
  ShadowTransmittance Transmittance; // the translucent actors' (GPU-resident) triangles
  std::vector<LayerKey> Drawn; // per layer of the allocated maps
  std::vector<Caster> Casters; // this Run's
  Block Data{};
  StorageBuffer Buffer;
};

}

#endif
