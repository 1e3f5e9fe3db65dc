/**
 * Voxelize stage: the voxel volumes and the GL work around rendering actors into them.
 *
 * Actors are rendered by their own VTK mappers; vtkVoxelGIPass injects this stage's shader
 * code (ReplaceShaders*) so that every fragment adds its unlit colour, geometric normal and
 * emission to exact integer accumulators (one shader storage buffer per channel). A flag
 * volume marks voxels written by static actors: dynamic actors skip them, and ClearDynamic
 * clears everything else. Resolve turns the sums into the sampled volumes (albedo and normal
 * RGBA8, emission RGBA16F).
 */
#ifndef VoxelGIVoxelizer_h
#define VoxelGIVoxelizer_h

#include "GLHelpers.h"
#include "VoxelGrid.h"

#include <array>
#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;

namespace voxelgi
{

class Voxelizer
{
public:
  /// Channels of the accumulators: count, albedo rgb, normal xyz [, emission rgb].
  static constexpr int BaseChannels = 7;
  static constexpr int EmissionChannels = 3;

  /**
   * Allocate volumes and build programs for `resolution` (with or without emission).
   * Returns false with a message (naming the memory it needed) when it cannot.
   */
  bool Prepare(int resolution, bool emission, std::string& error);
  /// Bytes one resolution needs, for messages and for limits checks before allocating.
  static std::size_t RequiredBytes(int resolution, bool emission);

  /// Clear accumulators: all of them (and the flags), or only the non-static voxels.
  void Clear(vtkOpenGLRenderWindow* renWin, bool all);
  /// Bind buffers and the flag image for rendering actors into the accumulators.
  void BindForRendering() const;
  /// Make accumulator writes visible (between the static and the dynamic actors, and after).
  static void Barrier();
  /// Sums -> sampled volumes. `emissionScale` undoes the per-scene emission normalization.
  void Resolve(vtkOpenGLRenderWindow* renWin, float emissionScale);

  /// Shader injection into VTK's polydata mapper shaders (see vtkOpenGLRenderPass).
  static void PreReplaceShaders(std::string& geometry, std::string& fragment);
  void PostReplaceShaders(std::string& geometry, std::string& fragment) const;
  void SetShaderParameters(vtkShaderProgram* program, bool staticPass, const double emission[3]) const;

  /// Use GL_NV_conservative_raster (when the context has it) instead of dilating triangles.
  void SetHardwareConservative(bool on) { this->HardwareConservative = on; }
  bool GetHardwareConservative() const { return this->HardwareConservative; }

  int GetResolution() const { return this->Resolution; }
  bool HasEmission() const { return this->Emission; }
  std::size_t MemoryBytes() const;
  /// The part of MemoryBytes() that only emissive scenes need.
  std::size_t EmissionBytes() const;

  /// Read back: counts (one uint per voxel), flags (one byte), or a volume's RGBA texels.
  void ReadCounts(std::vector<unsigned int>& counts) const;
  void ReadFlags(std::vector<unsigned char>& flags) const;

  Volume3D AlbedoVolume;
  Volume3D NormalVolume;
  Volume3D EmissionVolume;

  void ReleaseGraphicsResources();

private:
  std::string Defines() const;

  int Resolution = 0;
  bool Emission = false;
  bool HardwareConservative = false;
  std::array<StorageBuffer, BaseChannels + EmissionChannels> Accumulators;
  Volume3D FlagVolume;
  ComputeProgram ClearProgram;
  ComputeProgram ResolveProgram;
};

}

#endif
