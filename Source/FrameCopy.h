/**
 * The frame as Present left VTK's framebuffer (colour and depth, in the framebuffer's own
 * formats and samples), so that a frame that shows the same image again copies it back
 * instead of VTK drawing its opaque steps again and the composite being blended: an
 * unchanged frame costs a copy, not a redraw. It is taken in the first such frame (a camera
 * move pays nothing for it). Only for framebuffer objects whose attachments can be read (VTK's
 * own windows, offscreen and ParaView's framebuffers); with a toolkit's default framebuffer
 * VTK keeps drawing. The copy is as large as the framebuffer (VTK's own is the same size).
 */
#ifndef VoxelGIFrameCopy_h
#define VoxelGIFrameCopy_h

#include "vtkSmartPointer.h" // for vtkSmartPointer

class vtkOpenGLFramebufferObject;
class vtkRenderbuffer;
class vtkWindow;

namespace voxelgi
{
struct Frame;

class FrameCopy
{
public:
  FrameCopy();
  ~FrameCopy();

  /// Copy the frame's viewport of the bound draw framebuffer.
  void Store(const Frame& frame);
  /// True when it holds a copy taken from the bound draw framebuffer, its attachments and the
  /// frame's viewport as they are now.
  bool Holds(const Frame& frame) const;
  /// Copy it back into the bound draw framebuffer (when it Holds the frame).
  void Restore(const Frame& frame);
  /// What is held no longer shows the frame (the image changed).
  void Forget() { this->Held = false; }
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  FrameCopy(const FrameCopy&) = delete;
  FrameCopy& operator=(const FrameCopy&) = delete;

  /// The bound draw framebuffer, its colour and depth attachments and the viewport.
  struct Target
  {
    int Framebuffer = 0;
    int Buffer = 0; // the draw buffer (a colour attachment)
    int Color[5] = {}; // name, internal format, samples, width, height
    int Depth[5] = {};
    int Viewport[4] = {};
    bool operator==(const Target& other) const;
  };
  static bool Describe(const Frame& frame, Target& target);
  void Blit(const Frame& frame, bool store);

  Target Source;
  bool Held = false;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Copy;
  vtkSmartPointer<vtkRenderbuffer> Color;
  vtkSmartPointer<vtkRenderbuffer> Depth;
};

}

#endif
