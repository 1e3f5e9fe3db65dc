#include "WindowFollower.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkOpenGLRenderWindow.h"

namespace voxelgi
{

WindowFollower::WindowFollower(std::function<void(vtkOpenGLRenderWindow*)> release)
  : Release(std::move(release))
{
  this->Deleted->SetClientData(this);
  this->Deleted->SetCallback([](vtkObject*, unsigned long, void* follower, void*) {
    static_cast<WindowFollower*>(follower)->Follow(nullptr);
  });
}

WindowFollower::~WindowFollower()
{
  this->Follow(nullptr);
}

void WindowFollower::Follow(vtkOpenGLRenderWindow* window)
{
  if (window == this->Window.GetPointer())
  {
    return;
  }
  if (vtkOpenGLRenderWindow* old = this->Window)
  {
    old->RemoveObserver(this->Observer);
    old->PushContext();
    this->Release(old);
    old->PopContext();
  }
  this->Window = window;
  this->Observer = window ? window->AddObserver(vtkCommand::DeleteEvent, this->Deleted) : 0;
}

}
