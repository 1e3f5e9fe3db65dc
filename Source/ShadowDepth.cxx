#include "ShadowDepth.h"

#include "VoxelGIShaders.h"
#include "shader_interface.h"

#include "vtkActor.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtk_glew.h"

#include <array>

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

void ShadowDepth::Draw(
  vtkActor* actor, const SceneBuffers::Entry& buffers, vtkMatrix4x4* clipFromWorld)
{
  if (buffers.TriangleCount == 0)
  {
    return;
  }
  // clip <- world <- model <- shifted model, in double so that data far from the origin
  // stays exact; floats only for the product.
  vtkNew<vtkMatrix4x4> shifted;
  for (int a = 0; a < 3; ++a)
  {
    shifted->SetElement(a, 3, buffers.Shift[a]);
  }
  vtkNew<vtkMatrix4x4> worldFromModel;
  vtkMatrix4x4::Multiply4x4(actor->GetMatrix(), shifted, worldFromModel);
  vtkNew<vtkMatrix4x4> clipFromModel;
  vtkMatrix4x4::Multiply4x4(clipFromWorld, worldFromModel, clipFromModel);
  std::array<float, 16> m;
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      m[4 * c + r] = static_cast<float>(clipFromModel->GetElement(r, c));
    }
  }
  this->Program.SetMat4Array("shadowClipFromModel", 1, m.data());
  buffers.Vertices.Bind(VOXELGI_SCENE_VERTEX_BINDING);
  buffers.Triangles.Bind(VOXELGI_SCENE_TRIANGLE_BINDING);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * buffers.TriangleCount));
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
