#include "ShadowDepth.h"

#include "VoxelGIShaders.h"
#include "shader_interface.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtk_glew.h"

namespace voxelgi
{

bool ShadowDepth::Prepare(std::string& error)
{
  if (!this->Program.BuildOnce(
        shaders::shadow_depth_vert, "shadow map depth", error, "", shaders::shadow_depth_frag))
  {
    return false;
  }
  if (!this->VertexArray)
  {
    glGenVertexArrays(1, &this->VertexArray);
  }
  return true;
}

void ShadowDepth::Begin(vtkOpenGLRenderWindow* window)
{
  this->Program.Use(window);
  glBindVertexArray(this->VertexArray);
}

void ShadowDepth::Draw(const SceneBuffers::Entry& buffers, const float* clipFromModel)
{
  if (buffers.TriangleCount == 0)
  {
    return;
  }
  this->Program.SetMat4Array("shadowClipFromModel", 1, clipFromModel);
  buffers.Vertices.Bind(VOXELGI_SCENE_VERTEX_BINDING);
  // Indexed, so that a vertex shared by many triangles is transformed about once.
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers.Indices.GetHandle());
  glDrawElements(
    GL_TRIANGLES, static_cast<GLsizei>(3 * buffers.TriangleCount), GL_UNSIGNED_INT, nullptr);
}

void ShadowDepth::End()
{
  glBindVertexArray(0);
  glUseProgram(0);
}

void ShadowDepth::ReleaseGraphicsResources()
{
  this->Program.Release();
  if (this->VertexArray)
  {
    glDeleteVertexArrays(1, &this->VertexArray);
    this->VertexArray = 0;
  }
}

}
