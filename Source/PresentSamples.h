/**
 * Present's blend as a dispatch (present_samples.comp): each of VTK's samples in the
 * renderer's viewport that VTK's own depth puts on or in front of the G-buffer's surface
 * becomes s * scale + add, read and written in place in the bound framebuffer's colour
 * texture as an image. present.frag's quad does the same through the raster pipeline, whose
 * blending of every sample took 0.87 ms at 1080p with 8 samples on an H100 (its fragment work
 * runs on a few of its units). Where the framebuffer's colour or depth is not a texture of
 * level 0, its colour format is not one an image holds (rgba8, rgba16f, rgba32f) or the
 * context cannot store that many samples into an image, Run declines and Present draws the
 * quad.
 */
#ifndef VoxelGIPresentSamples_h
#define VoxelGIPresentSamples_h

#include "GLHelpers.h"

#include <string>

class vtkTextureObject;

namespace voxelgi
{
struct Frame;

class PresentSamples
{
public:
  /// Blend `scale` and `add` (Composite's) into the bound framebuffer, with the G-buffer's
  /// `depth`; false, doing nothing, where the framebuffer does not allow it.
  bool Run(const Frame& frame, vtkTextureObject* scale, vtkTextureObject* add,
    vtkTextureObject* depth);
  void ReleaseGraphicsResources();

private:
  GLProgram Program;
  std::string Refused; // the defines of a program that did not build: not tried again
};

}

#endif
