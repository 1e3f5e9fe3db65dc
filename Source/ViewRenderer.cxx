#include "ViewRenderer.h"

#include "vtkCamera.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"

namespace voxelgi
{

ViewRenderer::ViewRenderer()
  : Renderer(vtkSmartPointer<vtkOpenGLRenderer>::New())
{
  this->Renderer->SetActiveCamera(this->Camera);
  this->Renderer->AutomaticLightCreationOff();
  this->Renderer->LightFollowCameraOff();
  this->Renderer->InteractiveOff();
}

ViewRenderer::~ViewRenderer() = default;

vtkRenderer* ViewRenderer::Attach(vtkOpenGLRenderWindow* window)
{
  if (this->Renderer->GetRenderWindow() != window)
  {
    this->Renderer->SetRenderWindow(window);
    this->Renderer->UpdateLights(); // none: lighting complexity 0, unlit shaders
  }
  return this->Renderer;
}

void ViewRenderer::Release()
{
  this->Renderer->SetRenderWindow(nullptr);
}

}
