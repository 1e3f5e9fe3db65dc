/**
 * ViewRenderer: the pass's own renderer on the frame's window, for the stages that draw the
 * scene from another viewpoint than the user's.
 */
#ifndef VoxelGIViewRenderer_h
#define VoxelGIViewRenderer_h

#include "vtkNew.h"          // for vtkNew
#include "vtkSmartPointer.h" // for vtkSmartPointer

class vtkCamera;
class vtkOpenGLRenderer;
class vtkOpenGLRenderWindow;
class vtkRenderer;

namespace voxelgi
{

/**
 * A renderer of the pass's own on the frame's window, seeing through a camera of its own:
 * the stages that draw the scene from another viewpoint than the user's (voxelization from
 * the grid, shadow maps from the lights) hand it to the props' RenderOpaqueGeometry, and
 * VTK's mappers take their matrices from its camera (`ren->GetActiveCamera()`). The user's
 * renderer is never touched: its active camera stays the user's throughout, even for code
 * that runs while the mappers draw, and no ActiveCameraEvent fires. It has no lights (the
 * mappers build unlit shaders; these stages replace the shading or write depth only).
 */
class ViewRenderer
{
public:
  ViewRenderer();
  ~ViewRenderer();
  ViewRenderer(const ViewRenderer&) = delete;
  ViewRenderer& operator=(const ViewRenderer&) = delete;

  /// The renderer, on `window`.
  vtkRenderer* Attach(vtkOpenGLRenderWindow* window);
  /// The camera it sees through: aim it before drawing.
  vtkCamera* GetCamera() const { return this->Camera; }
  /// Leave the window (the context current).
  void Release();

private:
  vtkSmartPointer<vtkOpenGLRenderer> Renderer;
  vtkNew<vtkCamera> Camera;
};

}

#endif
