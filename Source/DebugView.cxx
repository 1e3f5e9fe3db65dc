#include "DebugView.h"

#include "Frame.h"
#include "GridView.h"
#include "LightVoxels.h"
#include "VoxelGIShaders.h"
#include "VoxelizePass.h"
#include "StageIds.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"
#include "vtk_glew.h"

#include <array>

namespace voxelgi
{

bool DebugView::Prepare(const Frame& frame, std::string& error)
{
  if (!this->Image)
  {
    this->Image = NewImageTexture(frame.Window, GL_RGBA8, frame.Width, frame.Height);
  }
  this->Image->Resize(frame.Width, frame.Height);
  return this->Program.BuildOnce(shaders::debug_view_comp, "debug view", error);
}

void DebugView::Run(const Frame& frame)
{
  ScopedStage stage(*frame.Clock, stage::DebugView);
  GLProgram& p = this->Program;
  p.Use(frame.Window);
  const VoxelizePass& voxels = *frame.Voxelization;
  const Volume3D& radiance = frame.Lighting->GetRadiance();
  float columnMajor[16];
  GridFromNDC(frame.Renderer, frame.Grid, columnMajor);

  SamplerBindings samplers(frame.Window);
  p.SetInt("voxelAlbedo", samplers.Add(voxels.GetAlbedo()));
  p.SetInt("voxelNormal", samplers.Add(voxels.GetNormal()));
  // Volumes a scene lacks still need a 3D texture of the sampler's type behind them.
  p.SetInt("voxelEmission",
    samplers.Add(voxels.HasEmission() ? voxels.GetEmission() : voxels.GetAlbedo()));
  p.SetInt("voxelRadiance", samplers.Add(radiance.IsAllocated() ? radiance : voxels.GetAlbedo()));
  p.SetInt("hasEmission", voxels.HasEmission() ? 1 : 0);
  p.SetMat4Array("voxelFromNDC", 1, columnMajor);
  p.SetInt("debugView", frame.Config.DebugView);
  const double* bg = frame.Renderer->GetBackground();
  p.SetVec3Array("backgroundColor", 1,
    std::array<float, 3>{ { static_cast<float>(bg[0]), static_cast<float>(bg[1]),
      static_cast<float>(bg[2]) } }.data());
  if (!(samplers.Complete()))
  {
    return;
  }
  BindImage2D(0, this->Image, GL_WRITE_ONLY, GL_RGBA8);
  p.DispatchImage(frame.Width, frame.Height, 8);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void DebugView::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Image)
  {
    this->Image->ReleaseGraphicsResources(window);
  }
  this->Image = nullptr;
  this->Program.Release();
}

}
