/**
 * DebugView stage (debug_view.comp, a compute dispatch in 8x8 tiles): the voxel volumes as an
 * RGBA8 image of the viewport, seen through the renderer's camera, so a user can check what
 * was voxelized (albedo, normal, emission) and how it is lit (radiance): the frame's volumes
 * (Frame::Voxelization, Frame::Lighting). Present draws it.
 */
#ifndef VoxelGIDebugView_h
#define VoxelGIDebugView_h

#include "GLHelpers.h"

#include "vtkSmartPointer.h"  // for vtkSmartPointer
#include "vtkTextureObject.h" // for vtkSmartPointer

#include <string>

class vtkWindow;

namespace voxelgi
{
struct Frame;

class DebugView
{
public:
  /// Size the image for the frame's viewport; build the program.
  bool Prepare(const Frame& frame, std::string& error);
  /// Render the frame's voxel debug view into the image.
  void Run(const Frame& frame);
  vtkTextureObject* GetImage() const { return this->Image; }
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  GLProgram Program;
  vtkSmartPointer<vtkTextureObject> Image;
};

}

#endif
