/**
 * Mipmap stage (voxel_mipmap.comp): the radiance volume's levels of detail for cone tracing. Anisotropic: six
 * directional volumes at half resolution with full mip chains, built level by level by a
 * compute shader (front-to-back integration per direction, then average). Isotropic: the
 * radiance volume's own mip chain, box filtered.
 */
#ifndef VoxelGIVoxelMipmap_h
#define VoxelGIVoxelMipmap_h

#include "GLHelpers.h"

#include <array>
#include <string>

class vtkOpenGLRenderWindow;
class vtkWindow;

namespace voxelgi
{
struct Frame;
struct Settings;
class LightVoxels;
class VoxelizePass;

class VoxelMipmap
{
public:
  VoxelMipmap(const VoxelizePass& voxels, LightVoxels& lighting)
    : Voxels(voxels)
    , Lighting(lighting)
  {
  }

  /// Allocate the directional volumes for the frame's grid (anisotropic mipmaps only).
  bool Prepare(const Frame& frame, std::string& error);
  /// The bytes Prepare allocates for a grid of `resolution` with `settings`.
  static std::size_t RequiredBytes(int resolution, const Settings& settings);
  /// Rebuild all levels from the radiance volume.
  void Run(const Frame& frame);
  /// Run() without timing it (inside the bounces).
  void Build(vtkOpenGLRenderWindow* renWin);
  bool IsAnisotropic() const { return this->Anisotropic; }

  /// Directions a cone travels: +x, -x, +y, -y, +z, -z.
  std::array<Volume3D, 6> Directional;
  /// Mean occupancy of partial (r) and full (g) voxels at the directional levels, with which
  /// the build tells a medium from surfaces' coverage; only in scenes with media.
  Volume3D Medium;
  std::size_t MemoryBytes() const;
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  const VoxelizePass& Voxels;
  LightVoxels& Lighting;
  bool Anisotropic = true;
  GLProgram Program;
};

/// Number of mip levels of a cube of `resolution` voxels down to one voxel.
int MipLevels(int resolution);

}

#endif
