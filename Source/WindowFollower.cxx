#include "WindowFollower.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTimeStamp.h"

namespace voxelgi
{

WindowFollower::WindowFollower(std::function<void(vtkOpenGLRenderWindow*)> release)
  : Release(std::move(release))
{
  this->Deleted->SetClientData(this);
  this->Deleted->SetCallback([](vtkObject*, unsigned long, void* follower, void*) {
    static_cast<WindowFollower*>(follower)->Follow(nullptr);
  });
  this->Started->SetClientData(this);
  this->Started->SetCallback([](vtkObject*, unsigned long, void* follower, void*) {
    auto& starts = static_cast<WindowFollower*>(follower)->Starts;
    vtkTimeStamp now;
    now.Modified();
    starts = { { now.GetMTime(), starts[0] } };
  });
}

WindowFollower::~WindowFollower()
{
  this->Follow(nullptr);
}

void WindowFollower::Follow(vtkOpenGLRenderWindow* window)
{
  if (window)
  {
    vtkTimeStamp now;
    now.Modified();
    this->ServedAt = now.GetMTime();
  }
  if (window == this->Window.GetPointer())
  {
    return;
  }
  if (vtkOpenGLRenderWindow* old = this->Window)
  {
    old->RemoveObserver(this->Observers[0]);
    old->RemoveObserver(this->Observers[1]);
    this->InContext(old, [this, old] { this->Release(old); });
  }
  this->Window = window;
  this->Starts = { { 0, 0 } };
  this->Observers[0] = window ? window->AddObserver(vtkCommand::DeleteEvent, this->Deleted) : 0;
  // Ahead of other StartEvent observers: a distributed view runs its ranks' part from one.
  this->Observers[1] =
    window ? window->AddObserver(vtkCommand::StartEvent, this->Started, 1.0f) : 0;
}

void WindowFollower::InContext(vtkWindow* window, const std::function<void()>& work) const
{
  vtkOpenGLRenderWindow* context =
    this->Window ? this->Window.GetPointer() : vtkOpenGLRenderWindow::SafeDownCast(window);
  if (context)
  {
    context->PushContext();
  }
  work();
  if (context)
  {
    context->PopContext();
  }
}

}
