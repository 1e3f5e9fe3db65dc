/**
 * GBuffer stage: an internal render pass in which VTK renders the frame's camera, lights and
 * opaque geometry (its own shading kept in attachment 0) into the pass's framebuffer, while
 * fragment code it injects into the polydata mappers (gbuffer.frag) adds the view-space
 * normal and specular power (attachment 1) and the albedo and specular intensity
 * (attachment 2); depth goes to a float texture (the vtkSSAOPass pattern). A delegate that is
 * not a vtkRenderStepsPass renders whole into attachment 0. In a multisampled window VTK
 * draws into multisampled renderbuffers with the window's sample count, resolved into the
 * textures (colours averaged, so edges and lines keep VTK's anti-aliasing; depth from one
 * sample; the ambient attachment's alpha becomes the pixel's coverage by polydata surfaces).
 */
#ifndef VoxelGIGBufferPass_h
#define VoxelGIGBufferPass_h

#include "vtkNew.h"              // for vtkNew
#include "vtkRenderPass.h"       // for the superclass
#include "vtkSmartPointer.h"     // for vtkSmartPointer
#include "vtkTextureObject.h"    // for vtkSmartPointer

#include <string>

class vtkAbstractMapper;
class vtkCameraPass;
class vtkOpenGLFramebufferObject;
class vtkRenderbuffer;
class vtkRenderPassCollection;
class vtkProp;
class vtkSequencePass;
class vtkShaderProgram;

namespace voxelgi
{
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
  /// Render the state's props through the delegate's opaque steps (Run sets up the state).
  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  vtkTextureObject* GetColor() const { return this->Color; }
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

  /// Bind the framebuffer VTK draws into (saving the current bindings) / restore.
  void Begin();
  void End();
  /// Average the multisampled attachments into the textures.
  void Resolve();
  /// The framebuffer VTK draws into: the multisampled one, or the textures' own.
  vtkOpenGLFramebufferObject* Target() const;
  /// Attach the textures to the textures' framebuffer (bound).
  void AttachTextures();
  static void DisableDataBlending();

  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkSmartPointer<vtkTextureObject> Color;
  vtkSmartPointer<vtkTextureObject> Normal;
  vtkSmartPointer<vtkTextureObject> Material;
  vtkSmartPointer<vtkTextureObject> Ambient;
  vtkSmartPointer<vtkTextureObject> Depth;
  // With multisampling: the framebuffer VTK draws into, and its attachments.
  unsigned int Samples = 0;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Multisampled;
  vtkSmartPointer<vtkRenderbuffer> SampleBuffers[5]; // 4 colours, depth
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
