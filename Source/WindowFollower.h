/**
 * The release rule's other half: GL objects are freed with their own context current. The
 * pass follows the window it renders to; when it moves to another window, is destroyed, or
 * the window goes away (its DeleteEvent comes while its context still exists), everything is
 * released with that window's context pushed. A release asked for from outside (a renderer
 * leaving its window while another window's context is current) pushes it too.
 *
 * It also counts the window's renders (their StartEvents): a pass that traces another's
 * voxels asks whether they were made in this render or the last, and a pass whether it took
 * part in the last.
 */
#ifndef VoxelGIWindowFollower_h
#define VoxelGIWindowFollower_h

#include "vtkNew.h"         // for vtkNew
#include "vtkType.h"        // for vtkMTimeType
#include "vtkWeakPointer.h" // for vtkWeakPointer

#include <array>
#include <functional>

class vtkCallbackCommand;
class vtkOpenGLRenderWindow;
class vtkWindow;

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

  /// Runs `work` with the context of the followed window (else `window`, if an OpenGL
  /// window) current, restoring the current one after.
  void InContext(vtkWindow* window, const std::function<void()>& work) const;

  /// When the followed window's current render ([0]) and the one before ([1]) started, on
  /// VTK's modification clock (0: not seen).
  std::array<vtkMTimeType, 2> RenderStarts() const { return this->Starts; }

  /// Whether the pass followed the window (Follow) in its current render, or no render of it
  /// was seen: a pass left out of the window's last render has no GI in it.
  bool Served() const { return this->Starts[0] == 0 || this->ServedAt > this->Starts[0]; }

private:
  std::function<void(vtkOpenGLRenderWindow*)> Release;
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  vtkNew<vtkCallbackCommand> Deleted;
  vtkNew<vtkCallbackCommand> Started;
  unsigned long Observers[2] = { 0, 0 };
  std::array<vtkMTimeType, 2> Starts{ { 0, 0 } };
  vtkMTimeType ServedAt = 0;
};

}

#endif
