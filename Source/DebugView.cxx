#include "VoxelDebugView.h"

#include "GridView.h"
#include "VoxelGIShaders.h"
#include "VoxelGrid.h"
#include "GLHelpers.h"
#include "Voxelizer.h"

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

void VoxelDebugView::Render(vtkRenderer* renderer, const VoxelGrid& grid, const Voxelizer& voxels,
  const Volume3D& radiance, int view)
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
  float columnMajor[16];
  GridFromNDC(renderer, grid, columnMajor);

  SamplerBindings samplers(renWin);
  program->SetUniformi("voxelAlbedo", samplers.Add(voxels.AlbedoVolume));
  program->SetUniformi("voxelNormal", samplers.Add(voxels.NormalVolume));
  // Volumes a scene lacks still need a 3D texture of the sampler's type behind them.
  program->SetUniformi("voxelEmission",
    samplers.Add(voxels.HasEmission() ? voxels.EmissionVolume : voxels.AlbedoVolume));
  program->SetUniformi("voxelRadiance",
    samplers.Add(radiance.IsAllocated() ? radiance : voxels.AlbedoVolume));
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
