/**
 * GBuffer stage: an internal render pass in which VTK renders the frame's camera, lights and
 * opaque geometry through fragment code it injects into the polydata mappers (gbuffer.frag):
 * besides VTK's shaded colour, the surface, packed (the view-space normal, specular power and
 * the pixel's kind; gbuffer_encoding.glsl), the albedo and specular intensity and the ambient
 * term, one sample a pixel, with a float depth. A delegate that is not a vtkRenderStepsPass
 * renders whole. Two ways, chosen by what the GPU guarantees:
 * - Where fragments of a pixel can store in draw order (a fragment-shader interlock, or a
 *   rasterizer that shades each tile in order) and the framebuffer has a sample near each
 *   pixel's centre (one sample, or NVIDIA's 8x), VTK's own draw of its image, into the
 *   frame's framebuffer with the window's multisampling, stores the G-buffer into images as
 *   it goes (the nearest fragment covering that sample wins): the scene is drawn once.
 * - Otherwise VTK draws the same steps twice: into the pass's framebuffer at one sample per
 *   pixel (attachments 0-3, the vtkSSAOPass pattern; Run), and its own image (RenderVTK),
 *   through the same shaders, so that a mapper keeps one shader program for both draws.
 */
#ifndef VoxelGIGBufferPass_h
#define VoxelGIGBufferPass_h

#include "GLHelpers.h"           // for GLProgram
#include "vtkNew.h"              // for vtkNew
#include "vtkRenderPass.h"       // for the superclass
#include "vtkSmartPointer.h"     // for vtkSmartPointer
#include "vtkTextureObject.h"    // for vtkSmartPointer

#include <string>

class vtkAbstractMapper;
class vtkCameraPass;
class vtkOpenGLFramebufferObject;
class vtkRenderPassCollection;
class vtkProp;
class vtkSequencePass;
class vtkShaderProgram;

namespace voxelgi
{

/// Of `count` sample positions (x, y pairs within the pixel, from 0 to 1), the first of those
/// nearest the pixel's centre; `distance` says how far from it, in pixels. GL-free.
int CentralSample(const float* positions, int count, float& distance);
/// The farthest the central sample may lie from the centre for VTK's own draw to make the
/// G-buffer (GBufferPass::Prepare).
constexpr float MaxCentralSampleDistance = 0.25f;
struct Frame;

class GBufferPass : public vtkRenderPass
{
public:
  static GBufferPass* New();
  vtkTypeMacro(GBufferPass, vtkRenderPass);

  /// Create or resize the textures and the framebuffer for the frame's viewport.
  bool Prepare(const Frame& frame, std::string& error);
  /// Render the frame's opaque geometry into the G-buffer.
  void Run(const Frame& frame);
  /// Render the same steps as VTK would into the frame's framebuffer, unless Run did in this
  /// render (FromVTKDraw); returns the props drawn.
  int RenderVTK(const Frame& frame);
  /// Whether VTK's own draw of its image makes the G-buffer (Prepare decides).
  bool IsFromVTKDraw() const { return this->FromVTKDraw; }
  /// Render the state's props through the delegate's opaque steps (Run sets up the state).
  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  vtkTextureObject* GetColor() const { return this->Color; }
  /// The packed surface: normal, specular power and kind (gbuffer_encoding.glsl).
  vtkTextureObject* GetNormal() const { return this->Normal; }
  vtkTextureObject* GetMaterial() const { return this->Material; }
  /// VTK's ambient term of surfaces that do not emit: the part AO may darken.
  vtkTextureObject* GetAmbient() const { return this->Ambient; }
  vtkTextureObject* GetDepth() const { return this->Depth; }

  // Shader injection into the mappers, through the render pass object all G-buffers of a
  // thread share (vtkOpenGLRenderPass's PostReplaceShaderValues and SetShaderParameters).
  bool ReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop);
  bool SetParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop);

protected:
  GBufferPass();
  ~GBufferPass() override;

private:
  GBufferPass(const GBufferPass&) = delete;
  void operator=(const GBufferPass&) = delete;

  /// What Render() draws: VTK's camera, lights and opaque steps (or the whole delegate).
  void SelectOpaque(const Frame& frame);
  /// Draw the state's props through the opaque steps into `target` (null: the state's own
  /// framebuffer, as VTK draws).
  void Draw(const Frame& frame, vtkOpenGLFramebufferObject* target);
  /// Bind the G-buffer's framebuffer (saving the current bindings) / restore.
  void Begin();
  void End();
  static void SetDataBlending(bool polyData);
  /// Whether the current context's fragments of one pixel can store in draw order.
  static bool StoresInDrawOrder();
  /// Clear and bind the G-buffer's images, and draw VTK's image into the frame's framebuffer.
  void DrawWithVTK(const Frame& frame);
  /// The current framebuffer's sample nearest the pixel's centre (CentralSample); returns
  /// its distance from the centre in pixels.
  float FindCentralSample();

  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  GLProgram Clear; // the images VTK's draw stores into (gbuffer_clear.comp)
  vtkSmartPointer<vtkTextureObject> Color;
  vtkSmartPointer<vtkTextureObject> Normal;
  vtkSmartPointer<vtkTextureObject> Material;
  vtkSmartPointer<vtkTextureObject> Ambient;
  vtkSmartPointer<vtkTextureObject> Depth;
  bool IntoGBuffer = false; // Render() draws into the G-buffer, else into VTK's framebuffer
  bool FromVTKDraw = false;
  int InDrawOrder = -1; // whether fragments store in draw order (-1: not asked yet)
  int Origin[2] = { 0, 0 };  // the viewport's origin in the window (gbuffer_images.glsl)
  int Samples = -1;            // the framebuffer's sample count FindCentralSample last saw,
  int CentralSample = 0;       // its sample nearest the pixel's centre,
  float CentralDistance = 0.f; // and that sample's distance from it in pixels
  bool Drawn = false;        // DrawWithVTK drew VTK's image in the render that started at
  vtkMTimeType DrawnIn = 0;  // DrawnIn, and RenderVTK has not asked for it yet
  bool BlendWasEnabled[3] = { false, false, false };
  bool LitScene = true;
  vtkRenderPass* Opaque = nullptr; // what Render() runs this frame
  // Camera + lights + opaque steps of a vtkRenderStepsPass delegate.
  vtkNew<vtkCameraPass> OpaqueCamera;
  vtkNew<vtkSequencePass> OpaqueSequence;
  vtkNew<vtkRenderPassCollection> OpaquePasses;
};

}

#endif
