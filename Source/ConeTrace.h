/**
 * ConeTrace and Composite stages: a full-screen pass over the G-buffer, at the trace
 * resolution, traces diffuse, specular and shadow cones through the voxel mipmaps; a second
 * one at the image's resolution upsamples that (edge-aware) and composites it with VTK's
 * shading into a float image (plus an indirect + AO image); Present then draws the result
 * into VTK's framebuffer with the scene depth.
 */
#ifndef VoxelGIConeTracer_h
#define VoxelGIConeTracer_h

#include "vtkOpenGLFramebufferObject.h" // for vtkSmartPointer
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"             // for vtkSmartPointer

#include <memory>
#include <vector>

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkTextureObject;
class vtkWindow;

namespace voxelgi
{
class GBuffer;
class VoxelLighting;
class VoxelMipmap;
struct ConeSettings;
struct VoxelGrid;

/// Per-pixel settings of the trace and composite.
struct TraceSettings
{
  float StartOffset = 1.f;
  float IndirectIntensity = 1.f;
  float SpecularIntensity = 1.f;
  bool SpecularCone = true;
  float AOStrength = 0.5f;
  float AOFalloff = 0.05f;
  bool ConeShadows = true;
  float ShadowTanHalf = 0.05f;
  int View = 0;      // 0 composite, 1 direct, 2 indirect, 3 AO
  float Scale = 1.f; // trace resolution / image resolution
};

class ConeTracer
{
public:
  ConeTracer();
  ~ConeTracer();

  /// Trace and composite into the float images.
  void Trace(vtkRenderer* renderer, const VoxelGrid& grid, const GBuffer& gbuffer,
    const VoxelLighting& lighting, const VoxelMipmap& mips, const ConeSettings& cones,
    const TraceSettings& settings);
  /// Draw the composite into the currently bound framebuffer at (x, y, w, h), with depth.
  void Present(vtkOpenGLRenderWindow* renWin, const GBuffer& gbuffer, int x, int y, int w, int h);

  /// Read back the last composite (0) or indirect + AO image (1) as RGBA floats.
  bool Read(vtkOpenGLRenderWindow* renWin, int image, std::vector<float>& rgba, int& w, int& h);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  std::unique_ptr<vtkOpenGLQuadHelper> TraceQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> CompositeQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> PresentQuad;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkSmartPointer<vtkTextureObject> TraceIndirect; // trace resolution
  vtkSmartPointer<vtkTextureObject> TraceShadowed;
  vtkSmartPointer<vtkTextureObject> Composite; // image resolution
  vtkSmartPointer<vtkTextureObject> Indirect;
};

}

#endif
