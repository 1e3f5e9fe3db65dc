#include "GBuffer.h"

#include "VoxelGIShaders.h"

#include "vtkActor.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkProperty.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

namespace voxelgi
{

namespace
{
vtkSmartPointer<vtkTextureObject> NewTexture(vtkOpenGLRenderWindow* renWin, int internalFormat)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(renWin);
  texture->SetInternalFormat(internalFormat);
  texture->SetFormat(GL_RGBA);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  return texture;
}
}

void GBuffer::Prepare(vtkOpenGLRenderWindow* renWin, int width, int height)
{
  if (!this->Framebuffer)
  {
    this->Color = NewTexture(renWin, GL_RGBA16F);
    this->Color->Allocate2D(width, height, 4, VTK_FLOAT);
    this->Normal = NewTexture(renWin, GL_RGBA16F);
    this->Normal->Allocate2D(width, height, 4, VTK_FLOAT);
    this->Material = NewTexture(renWin, GL_RGBA8);
    this->Material->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
    this->Depth = vtkSmartPointer<vtkTextureObject>::New();
    this->Depth->SetContext(renWin);
    this->Depth->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Depth->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->Depth->AllocateDepth(width, height, vtkTextureObject::Float32);
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Framebuffer->SetContext(renWin);
  }
  this->Color->Resize(width, height);
  this->Normal->Resize(width, height);
  this->Material->Resize(width, height);
  this->Depth->Resize(width, height);
}

void GBuffer::Begin()
{
  this->Framebuffer->SaveCurrentBindingsAndBuffers();
  this->Framebuffer->Bind();
  this->Framebuffer->AddColorAttachment(0, this->Color);
  this->Framebuffer->AddColorAttachment(1, this->Normal);
  this->Framebuffer->AddColorAttachment(2, this->Material);
  this->Framebuffer->AddDepthAttachment(this->Depth);
  this->Framebuffer->ActivateDrawBuffers(3);
  this->Framebuffer->StartNonOrtho(this->Color->GetWidth(), this->Color->GetHeight());
  for (unsigned int i = 0; i < 2; ++i)
  {
    this->BlendWasEnabled[i] = glIsEnabledi(GL_BLEND, i + 1) == GL_TRUE;
  }
  DisableDataBlending();
}

void GBuffer::DisableDataBlending()
{
  // VTK blends its opaque pass; the data attachments must be written as they are.
  glDisablei(GL_BLEND, 1);
  glDisablei(GL_BLEND, 2);
}

void GBuffer::End()
{
  for (unsigned int i = 0; i < 2; ++i)
  {
    if (this->BlendWasEnabled[i])
    {
      glEnablei(GL_BLEND, i + 1);
    }
  }
  this->Framebuffer->UnBind();
  this->Framebuffer->RestorePreviousBindingsAndBuffers();
}

void GBuffer::PostReplaceShaders(std::string& fragment, vtkProp* prop, bool litScene)
{
  std::string defines;
  if (fragment.find("normalVCVSOutput") != std::string::npos)
  {
    defines += "#define VOXELGI_HAS_NORMAL\n";
  }
  if (fragment.find("vec4 tcolor =") != std::string::npos)
  {
    defines += "#define VOXELGI_HAS_TEXTURE\n";
  }
  if (fragment.find("float specularPower =") != std::string::npos)
  {
    defines += "#define VOXELGI_HAS_SPECULAR\n";
  }
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (!litScene && actor && actor->GetProperty()->GetLighting())
  {
    defines += "#define VOXELGI_AMBIENT_ONLY\n";
  }
  vtkShaderProgram::Substitute(fragment, "//VTK::System::Dec", "//VTK::System::Dec\n" + defines);
  const std::size_t end = fragment.rfind('}');
  if (end != std::string::npos)
  {
    fragment.insert(end, shaders::gbuffer_frag);
  }
}

void GBuffer::SetShaderParameters(vtkAbstractMapper* mapper)
{
  this->Framebuffer->ActivateDrawBuffers(vtkOpenGLPolyDataMapper::SafeDownCast(mapper) ? 3 : 1);
  // Before every draw: VTK's state handling may have re-enabled blending for all buffers.
  DisableDataBlending();
}

void GBuffer::ReleaseGraphicsResources(vtkWindow* window)
{
  for (vtkTextureObject* texture : { this->Color.Get(), this->Normal.Get(), this->Material.Get(),
         this->Depth.Get() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(window);
    }
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  this->Framebuffer = nullptr;
  this->Color = this->Normal = this->Material = this->Depth = nullptr;
}

}
