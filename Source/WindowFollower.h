/**
 * The release rule's other half: GL objects are freed with their own context current. The
 * pass follows the window it renders to; when it moves to another window, is destroyed, or
 * the window goes away (its DeleteEvent comes while its context still exists), everything is
 * released with that window's context pushed.
 */
#ifndef VoxelGIWindowFollower_h
#define VoxelGIWindowFollower_h

#include "vtkNew.h"         // for vtkNew
#include "vtkWeakPointer.h" // for vtkWeakPointer

#include <functional>

class vtkCallbackCommand;
class vtkOpenGLRenderWindow;

namespace voxelgi
{

class WindowFollower
{
public:
  /// `release` frees every GL object of the window it is given (its context is current).
  explicit WindowFollower(std::function<void(vtkOpenGLRenderWindow*)> release);
  ~WindowFollower();
  WindowFollower(const WindowFollower&) = delete;
  WindowFollower& operator=(const WindowFollower&) = delete;

  /// Release everything on the window followed so far (unless it is `window`) and follow
  /// `window` (null: none).
  void Follow(vtkOpenGLRenderWindow* window);
  vtkOpenGLRenderWindow* Get() const { return this->Window; }

private:
  std::function<void(vtkOpenGLRenderWindow*)> Release;
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  vtkNew<vtkCallbackCommand> Deleted;
  unsigned long Observer = 0;
};

}

#endif
