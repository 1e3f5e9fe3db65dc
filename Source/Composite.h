/**
 * Composite stage (composite.comp, a compute dispatch in 8x8 tiles): at the image's
 * resolution, VTK's shading (the direct term) minus what the lights' shadows take away, its
 * ambient term darkened by AO, plus the indirect light, gathered from the traced samples of
 * the same surface around each pixel (a tent that weighs the trace's four cone turns alike;
 * the shadows bilinear), into a float image (and an indirect + AO image, and the clamped
 * RGBA8 display image that Present draws).
 */
#ifndef VoxelGIComposite_h
#define VoxelGIComposite_h

#include "GLHelpers.h"

#include "vtkSmartPointer.h"  // for vtkSmartPointer
#include "vtkTextureObject.h" // for vtkSmartPointer

#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkWindow;

namespace voxelgi
{
struct Frame;
class ConeTrace;
class GBufferPass;

class Composite
{
public:
  Composite(const GBufferPass& gbuffer, const ConeTrace& trace);
  ~Composite();

  /// Size the images for the frame's viewport; build the program.
  bool Prepare(const Frame& frame, std::string& error);
  /// Composite into the float images.
  void Run(const Frame& frame);
  /// The last composite, clamped to RGBA8 for display.
  vtkTextureObject* GetDisplay() const { return this->Display; }
  /// Read back the last composite (0) or indirect + AO image (1) as RGBA floats.
  bool Read(vtkOpenGLRenderWindow* renWin, int image, std::vector<float>& rgba, int& w, int& h);
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  const GBufferPass& GBuffer;
  const ConeTrace& Trace;
  ComputeProgram Program;
  vtkSmartPointer<vtkTextureObject> Color; // composited linear colour
  vtkSmartPointer<vtkTextureObject> Indirect;
  vtkSmartPointer<vtkTextureObject> Display; // clamped RGBA8, what Present draws
};

}

#endif
