/**
 * Composite stage (composite.comp, a compute dispatch in 8x8 tiles): at the image's
 * resolution, VTK's shading (the direct term) minus what the lights' shadows take away, its
 * ambient term darkened by AO, plus the indirect light, gathered from the traced samples of
 * the same surface around each pixel (a tent that weighs the trace's four cone turns alike;
 * the shadows bilinear), into a float image (and an indirect + AO image), and the blend
 * Present applies to each of VTK's own samples: a scale and an added colour per pixel.
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
  /// Present's blend of VTK's image: each sample s becomes s * scale + add (rgb; the
  /// scale's alpha is 1 where the G-buffer has a surface).
  vtkTextureObject* GetPresentScale() const { return this->Scale; }
  vtkTextureObject* GetPresentAdd() const { return this->Add; }
  /// Read back the last composite (0) or indirect + AO image (1) as RGBA floats.
  bool Read(vtkOpenGLRenderWindow* renWin, int image, std::vector<float>& rgba, int& w, int& h);
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  const GBufferPass& GBuffer;
  const ConeTrace& Trace;
  GLProgram Program;
  vtkSmartPointer<vtkTextureObject> Color; // composited linear colour
  vtkSmartPointer<vtkTextureObject> Indirect;
  vtkSmartPointer<vtkTextureObject> Scale;
  vtkSmartPointer<vtkTextureObject> Add;
};

}

#endif
