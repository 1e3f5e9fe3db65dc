/**
 * GBuffer stage: VTK renders the opaque geometry (its own shading kept in attachment 0) into
 * the pass's framebuffer, while fragment code injected into its polydata mappers adds the
 * view-space normal and specular power (attachment 1) and the albedo and specular intensity
 * (attachment 2); depth goes to a float texture (the vtkSSAOPass pattern).
 */
#ifndef VoxelGIGBuffer_h
#define VoxelGIGBuffer_h

#include "vtkOpenGLFramebufferObject.h" // for vtkSmartPointer
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"             // for vtkSmartPointer

#include <string>

class vtkAbstractMapper;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkTextureObject;
class vtkWindow;

namespace voxelgi
{

class GBuffer
{
public:
  /// Create or resize the textures and the framebuffer for a w x h viewport.
  void Prepare(vtkOpenGLRenderWindow* renWin, int width, int height);
  /// Bind the framebuffer with all attachments (saving the current bindings) / restore.
  void Begin();
  void End();

  /// Shader injection (see vtkOpenGLRenderPass); `litScene`: the renderer has lights.
  static void PostReplaceShaders(std::string& fragment, vtkProp* prop, bool litScene);
  /// Polydata mappers write all attachments, other mappers only the colour.
  void SetShaderParameters(vtkAbstractMapper* mapper);

  vtkOpenGLFramebufferObject* GetFramebuffer() const { return this->Framebuffer; }
  vtkSmartPointer<vtkTextureObject> Color;
  vtkSmartPointer<vtkTextureObject> Normal;
  vtkSmartPointer<vtkTextureObject> Material;
  vtkSmartPointer<vtkTextureObject> Depth;

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  static void DisableDataBlending();

  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  bool BlendWasEnabled[2] = { false, false };
};

}

#endif
