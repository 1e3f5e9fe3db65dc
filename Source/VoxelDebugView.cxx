#include "VoxelDebugView.h"

#include "VoxelGIShaders.h"
#include "VoxelGrid.h"
#include "Voxelizer.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

namespace voxelgi
{

VoxelDebugView::VoxelDebugView() = default;
VoxelDebugView::~VoxelDebugView() = default;

void VoxelDebugView::Render(
  vtkRenderer* renderer, const VoxelGrid& grid, const Voxelizer& voxels, int view)
{
  auto* renWin = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  if (!this->Quad)
  {
    this->Quad.reset(new vtkOpenGLQuadHelper(renWin,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), shaders::debug_view_frag,
      ""));
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  vtkShaderProgram* program = this->Quad->Program;
  if (!program || !program->GetCompiled())
  {
    return;
  }

  int width = 0, height = 0, x = 0, y = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  const double aspect = height > 0 ? static_cast<double>(width) / height : 1.0;

  // NDC -> voxel coordinates, composed in double so that the large translations of a
  // far-from-origin scene cancel before anything is rounded to float.
  vtkNew<vtkMatrix4x4> ndcToWorld;
  ndcToWorld->DeepCopy(
    renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(aspect, -1, 1));
  ndcToWorld->Invert();
  vtkNew<vtkMatrix4x4> worldToVoxel;
  for (int a = 0; a < 3; ++a)
  {
    worldToVoxel->SetElement(a, a, 1.0 / grid.VoxelSize);
    worldToVoxel->SetElement(a, 3, -grid.Origin[a] / grid.VoxelSize);
  }
  vtkNew<vtkMatrix4x4> ndcToVoxel;
  vtkMatrix4x4::Multiply4x4(worldToVoxel, ndcToWorld, ndcToVoxel);
  float columnMajor[16];
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      columnMajor[c * 4 + r] = static_cast<float>(ndcToVoxel->GetElement(r, c));
    }
  }

  const int albedoUnit = voxels.AlbedoVolume.BindSampler(renWin);
  const int normalUnit = voxels.NormalVolume.BindSampler(renWin);
  // Without emission the sampler still needs a 3D texture of its type behind it.
  const Volume3D& emission = voxels.HasEmission() ? voxels.EmissionVolume : voxels.AlbedoVolume;
  const int emissionUnit = emission.BindSampler(renWin);

  program->SetUniformi("voxelAlbedo", albedoUnit);
  program->SetUniformi("voxelNormal", normalUnit);
  program->SetUniformi("voxelEmission", emissionUnit);
  program->SetUniformi("hasEmission", voxels.HasEmission() ? 1 : 0);
  program->SetUniformMatrix4x4("voxelFromNDC", columnMajor);
  program->SetUniformi("voxelResolution", grid.Resolution);
  program->SetUniformi("debugView", view);
  double* bg = renderer->GetBackground();
  const float background[3] = { static_cast<float>(bg[0]), static_cast<float>(bg[1]),
    static_cast<float>(bg[2]) };
  program->SetUniform3f("backgroundColor", background);

  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglViewport viewport(ostate);
  vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
  ostate->vtkglViewport(x, y, width, height);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_BLEND);
  this->Quad->Render();

  Volume3D::UnbindSampler(renWin, emissionUnit);
  Volume3D::UnbindSampler(renWin, normalUnit);
  Volume3D::UnbindSampler(renWin, albedoUnit);
}

void VoxelDebugView::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
}

}
