/**
 * ShadowMaps stage (shadow_maps.glsl reads them): a depth map per directional or spot light
 * and six (a cube) per point light, rendered from the light by VTK's own mappers (the actors
 * that are voxelized), and the matrices from grid coordinates to each map's clip space, in
 * the std140 layout of the `VoxelShadowBlock` uniform block. The voxel lighting and the
 * pixels' shadows (ConeTrace) look them up. Headlights have none: their shadows are hidden
 * behind what casts them.
 */
#ifndef VoxelGIShadowMaps_h
#define VoxelGIShadowMaps_h

#include "GLHelpers.h"
#include "MapperCopies.h"
#include "ViewRenderer.h" // for ViewRenderer
#include "shader_interface.h"

#include <string>

class vtkLight;
class vtkWindow;

namespace voxelgi
{
struct Frame;
class LightBlock;

class ShadowMaps
{
public:
  static constexpr int MaxLights = VOXELGI_MAX_LIGHTS;
  static constexpr int MaxLayers = VOXELGI_MAX_SHADOW_LAYERS;

  /// Choose the lights that get maps (block order) and allocate the maps at the frame's
  /// ShadowMapResolution. Returns false with a message when they cannot be allocated.
  bool Prepare(const Frame& frame, std::string& error);
  /// Render the maps with the frame's voxelized actors as casters; upload the block.
  void Run(const Frame& frame);
  /// Whether any light has a map.
  bool HasMaps() const { return this->Maps.Layers() > 0; }
  /// Bind the block at VOXELGI_SHADOW_BLOCK_BINDING and the maps to `program`'s (in use)
  /// `shadowMaps` sampler.
  void Bind(ComputeProgram& program, SamplerBindings& samplers) const;

  ShadowMapArray Maps;
  void ReleaseGraphicsResources(vtkWindow* window)
  {
    this->Maps.Release();
    this->Buffer.Release();
    this->Copies.ReleaseGraphicsResources(window);
    this->View.Release();
  }

private:
  /// std140 layout of shadow_maps.glsl's VoxelShadowBlock.
  struct Block
  {
    float Matrices[16 * MaxLayers]; // column-major grid -> clip, per layer
    int Lights[4 * MaxLights];      // first layer (-1: none), layers, valid for the pixels
    float Texels[4 * MaxLights];    // a texel's width in voxels: x + y * distance
    int Info[4];                    // every shadow-casting light has maps for the pixels
  };

  ViewRenderer View; // draws through each light's camera
  MapperCopies Copies; // depth-only draws never switch the user's mappers
  Block Data{};
  StorageBuffer Buffer;
};

}

#endif
