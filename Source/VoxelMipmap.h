/**
 * Mipmap stage: the radiance volume's levels of detail for cone tracing. Anisotropic: six
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

namespace voxelgi
{

class VoxelMipmap
{
public:
  /// Allocate the directional volumes for a radiance volume of `resolution` (anisotropic).
  bool Prepare(int resolution, bool anisotropic, std::string& error);
  /// Rebuild all levels from `radiance`.
  void Build(vtkOpenGLRenderWindow* renWin, Volume3D& radiance);
  bool IsAnisotropic() const { return this->Anisotropic; }

  /// Directions a cone travels: +x, -x, +y, -y, +z, -z.
  std::array<Volume3D, 6> Directional;
  std::size_t MemoryBytes() const;
  void ReleaseGraphicsResources();

private:
  bool Anisotropic = true;
  ComputeProgram Program;
};

/// Number of mip levels of a cube of `resolution` voxels down to one voxel.
int MipLevels(int resolution);

}

#endif
