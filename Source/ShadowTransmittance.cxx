#include "ShadowTransmittance.h"

#include "VoxelGIShaders.h"
#include "shader_interface.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtk_glew.h"

namespace voxelgi
{

namespace
{
unsigned int NewArray(int size, int layers)
{
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D_ARRAY, texture);
  glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_RGBA16F, size, size, layers);
  // Read texel by texel: a filtered depth would mix the nearest surface with what is behind.
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  return texture;
}
}

bool ShadowTransmittance::Prepare(int size, int layers, std::string& error)
{
  if (!this->Program.BuildOnce(shaders::shadow_transmittance_vert, "shadow map transmittance",
        error, "", shaders::shadow_transmittance_frag))
  {
    return false;
  }
  if (!this->VertexArray)
  {
    glGenVertexArrays(1, &this->VertexArray);
  }
  if (!this->Clear)
  {
    this->Clear = NewArray(1, 1);
    const float full[4] = { 1.0f, 1.0f, 1.0f, 0.0f };
    glBindTexture(GL_TEXTURE_2D_ARRAY, this->Clear);
    glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, full);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  }
  if (layers == 0 || (this->Texture && this->Size == size && this->Layers == layers))
  {
    if (layers == 0)
    {
      this->Release();
    }
    return true;
  }
  this->Release();
  ClearErrors();
  this->Texture = NewArray(size, layers);
  glGenFramebuffers(1, &this->Framebuffer);
  if (glGetError() != GL_NO_ERROR)
  {
    this->Release();
    error = "could not allocate the shadow maps' transmittance";
    return false;
  }
  this->Size = size;
  this->Layers = layers;
  return true;
}

void ShadowTransmittance::Release()
{
  if (this->Texture)
  {
    glDeleteTextures(1, &this->Texture);
    this->Texture = 0;
  }
  if (this->Framebuffer)
  {
    glDeleteFramebuffers(1, &this->Framebuffer);
    this->Framebuffer = 0;
  }
  this->Size = this->Layers = 0;
}

std::size_t ShadowTransmittance::Bytes() const
{
  return static_cast<std::size_t>(this->Size) * this->Size * this->Layers * 8;
}

void ShadowTransmittance::Begin(vtkOpenGLRenderWindow* window, int layer, unsigned int depthTexture)
{
  vtkOpenGLState* ostate = window->GetState();
  ostate->vtkglBindFramebuffer(GL_FRAMEBUFFER, this->Framebuffer);
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, this->Texture, 0, layer);
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depthTexture, 0, layer);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  ostate->vtkglClearColor(1.0, 1.0, 1.0, 0.0);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglDepthFunc(GL_LESS);
  ostate->vtkglDisable(GL_CULL_FACE);
  // rgb: the product of what each surface passes; alpha: the nearest surface's 1 - depth.
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ONE, GL_ONE);
  ostate->vtkglBlendEquationSeparate(GL_FUNC_ADD, GL_MAX);
  this->Program.Use(window);
  glBindVertexArray(this->VertexArray);
}

void ShadowTransmittance::Draw(
  const SceneBuffers::Entry& buffers, const float* clipFromModel, const float* rgba)
{
  if (buffers.TriangleCount == 0)
  {
    return;
  }
  this->Program.SetMat4Array("shadowClipFromModel", 1, clipFromModel);
  this->Program.SetInt("transmitColorMode", static_cast<int>(buffers.Colors));
  this->Program.SetVec4("transmitColor", rgba);
  buffers.Vertices.Bind(VOXELGI_SCENE_VERTEX_BINDING);
  if (buffers.Colors == TriangleColors::Cell)
  {
    buffers.CellColors.Bind(VOXELGI_SCENE_CELL_COLOR_BINDING);
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers.Indices.GetHandle());
  glDrawElements(
    GL_TRIANGLES, static_cast<GLsizei>(3 * buffers.TriangleCount), GL_UNSIGNED_INT, nullptr);
}

void ShadowTransmittance::End(vtkOpenGLRenderWindow* window)
{
  glBindVertexArray(0);
  glUseProgram(0);
  // Back to the opaque layers' state (ShadowMaps::Run restores VTK's after the last layer).
  vtkOpenGLState* ostate = window->GetState();
  ostate->vtkglBlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_ADD);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglDepthFunc(GL_LEQUAL);
}

void ShadowTransmittance::Bind(GLProgram& program, SamplerBindings& samplers) const
{
  program.SetInt("shadowTransmittance", samplers.AddTexture(
    this->Texture ? this->Texture : this->Clear, GL_TEXTURE_2D_ARRAY));
}

void ShadowTransmittance::ReleaseGraphicsResources()
{
  this->Release();
  this->Program.Release();
  if (this->VertexArray)
  {
    glDeleteVertexArrays(1, &this->VertexArray);
    this->VertexArray = 0;
  }
  if (this->Clear)
  {
    glDeleteTextures(1, &this->Clear);
    this->Clear = 0;
  }
}

}
