#include "ShadowMaps.h"

#include "Frame.h"
#include "LightBlock.h"
#include "VoxelGrid.h"
#include "vtkVoxelGIPass.h"

#include "vtkActor.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderer.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

namespace voxelgi
{

namespace
{
// Aim `camera` from the light over the grid and give it an explicit projection: orthographic
// over the grid's bounding sphere for a directional light, a perspective frustum of the
// spot's cone for a spot light.
void AimLightCamera(vtkCamera* camera, vtkLight* light, const VoxelGrid& grid)
{
  const glm::dvec3 center = grid.Center();
  const double radius = 0.5 * std::sqrt(3.0) * grid.Size();
  double position[3], focal[3];
  light->GetTransformedPosition(position);
  light->GetTransformedFocalPoint(focal);
  glm::dvec3 dir(focal[0] - position[0], focal[1] - position[1], focal[2] - position[2]);
  dir = glm::length(dir) > 0.0 ? glm::normalize(dir) : glm::dvec3(0, 0, -1);
  const glm::dvec3 up = std::abs(dir.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  vtkNew<vtkMatrix4x4> projection;
  if (!light->GetPositional())
  {
    const glm::dvec3 eye = center - dir * (2.0 * radius);
    camera->SetPosition(eye.x, eye.y, eye.z);
    camera->SetFocalPoint(center.x, center.y, center.z);
    // view depth -radius (near) .. -3 radius (far) -> NDC -1 .. 1
    projection->SetElement(0, 0, 1.0 / radius);
    projection->SetElement(1, 1, 1.0 / radius);
    projection->SetElement(2, 2, -1.0 / radius);
    projection->SetElement(2, 3, -2.0);
  }
  else
  {
    const glm::dvec3 eye(position[0], position[1], position[2]);
    const glm::dvec3 target = eye + dir;
    camera->SetPosition(eye.x, eye.y, eye.z);
    camera->SetFocalPoint(target.x, target.y, target.z);
    const double farPlane = glm::length(center - eye) + radius;
    const double nearPlane = std::max(farPlane * 1e-3, 1e-6 * radius);
    const double f =
      1.0 / std::tan(vtkMath::RadiansFromDegrees(std::min(light->GetConeAngle() + 2.0, 89.0)));
    projection->SetElement(0, 0, f);
    projection->SetElement(1, 1, f);
    projection->SetElement(2, 2, (farPlane + nearPlane) / (nearPlane - farPlane));
    projection->SetElement(2, 3, 2.0 * farPlane * nearPlane / (nearPlane - farPlane));
    projection->SetElement(3, 2, -1.0);
    projection->SetElement(3, 3, 0.0);
  }
  camera->SetViewUp(up.x, up.y, up.z);
  camera->SetExplicitProjectionTransformMatrix(projection);
  camera->SetUseExplicitProjectionTransformMatrix(true);
}
}

bool ShadowMaps::Prepare(const Frame& frame, const LightBlock& lights, std::string& error)
{
  const std::vector<vtkLight*>& used = lights.GetLights();
  int count = 0;
  for (std::size_t l = 0; l < MaxLights; ++l)
  {
    vtkLight* light = l < used.size() ? used[l] : nullptr;
    const bool shadowed = light && !light->LightTypeIsHeadlight() &&
      (!light->GetPositional() || light->GetConeAngle() < 90.0);
    this->Layers[l] = shadowed ? count++ : -1;
  }
  if (count == 0)
  {
    this->Maps.Release();
    return true;
  }
  if (!this->Maps.Allocate(frame.Config.ShadowMapResolution, count))
  {
    error = "could not allocate the shadow maps";
    return false;
  }
  return true;
}

void ShadowMaps::Run(const Frame& frame, const LightBlock& lights)
{
  if (!this->HasMaps())
  {
    return;
  }
  ScopedStage stage(*frame.Clock, vtkVoxelGIPass::STAGE_SHADOW_MAPS);
  // The casters draw through a renderer of ours whose camera is the light's: the user's
  // renderer and camera are left alone (see ViewRenderer).
  vtkRenderer* renderer = this->View.Attach(frame.Window);
  vtkCamera* camera = this->View.GetCamera();
  const VoxelGrid& grid = frame.Grid;
  const int size = this->Maps.Size();
  const std::vector<vtkLight*>& used = lights.GetLights();
  vtkOpenGLState* ostate = frame.Window->GetState();
  ostate->PushFramebufferBindings();
  {
    vtkOpenGLState::ScopedglViewport viewport(ostate);
    vtkOpenGLState::ScopedglEnableDisable scissor(ostate, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglEnableDisable depth(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable cull(ostate, GL_CULL_FACE);
    vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
    vtkOpenGLState::ScopedglDepthFunc depthFunc(ostate);
    ostate->vtkglViewport(0, 0, size, size);
    ostate->vtkglDisable(GL_SCISSOR_TEST);
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_LEQUAL);
    ostate->vtkglDepthMask(GL_TRUE);
    for (std::size_t l = 0; l < used.size() && l < MaxLights; ++l)
    {
      if (this->Layers[l] < 0)
      {
        continue;
      }
      AimLightCamera(camera, used[l], grid);
      ostate->vtkglBindFramebuffer(GL_FRAMEBUFFER, this->Maps.PrepareLayer(this->Layers[l]));
      ostate->vtkglClearDepth(1.0);
      ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
      for (const ActorRecord& record : *frame.Actors)
      {
        if (record.Actor)
        {
          this->Copies.Draw(record.Actor, renderer);
        }
      }
      // clip <- world <- grid, composed in double
      vtkNew<vtkMatrix4x4> clipFromWorld;
      clipFromWorld->DeepCopy(camera->GetCompositeProjectionTransformMatrix(1.0, -1, 1));
      vtkNew<vtkMatrix4x4> worldFromGrid;
      for (int a = 0; a < 3; ++a)
      {
        worldFromGrid->SetElement(a, a, grid.VoxelSize);
        worldFromGrid->SetElement(a, 3, grid.Origin[a]);
      }
      vtkNew<vtkMatrix4x4> clipFromGrid;
      vtkMatrix4x4::Multiply4x4(clipFromWorld, worldFromGrid, clipFromGrid);
      for (int r = 0; r < 4; ++r)
      {
        for (int c = 0; c < 4; ++c)
        {
          this->Matrices[16 * l + 4 * c + r] = static_cast<float>(clipFromGrid->GetElement(r, c));
        }
      }
    }
  }
  ostate->PopFramebufferBindings();
  this->Copies.Retain(*frame.Actors, frame.Window);
}

}
