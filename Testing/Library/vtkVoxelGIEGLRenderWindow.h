/**
 * @class   vtkVoxelGIEGLRenderWindow
 * @brief   Headless render window on an EGL context (GPU nodes without an X server).
 *
 * Debian's VTK 9.1 is built for GLX only. This window creates its own OpenGL 4.5 core
 * context through EGL (on the first EGL device, or the default display) with a pbuffer
 * surface and renders through vtkGenericOpenGLRenderWindow, so VTK programs and the voxel
 * GI pass run on headless NVIDIA machines, or on Mesa with EGL_PLATFORM=surfaceless.
 *
 * @code
 * vtkNew<vtkVoxelGIEGLRenderWindow> window;
 * window->SetSize(1920, 1080);
 * window->AddRenderer(renderer);
 * window->Render();
 * @endcode
 *
 * An EGL context is current in one thread at a time: a window rendered in a worker thread
 * must be released there (ReleaseCurrent()) before another thread renders it; until then
 * Render() reports an error and draws nothing.
 *
 * Note: Debian's GLEW 2.2 is built for GLX; under EGL its glewInit() reports "no GLX display"
 * after loading every OpenGL entry point, and VTK would log that at every render. This window
 * lets it be said once, with the remedy (preloading libVoxelGIGlewEGLShim.so).
 *
 * @sa vtkGenericOpenGLRenderWindow vtkVoxelGIPass
 */
#ifndef vtkVoxelGIEGLRenderWindow_h
#define vtkVoxelGIEGLRenderWindow_h

#include "vtkGenericOpenGLRenderWindow.h"
#include "vtkTestingVoxelGIModule.h" // for export macro

#include <memory> // for std::unique_ptr

class VTKTESTINGVOXELGI_EXPORT vtkVoxelGIEGLRenderWindow : public vtkGenericOpenGLRenderWindow
{
public:
  static vtkVoxelGIEGLRenderWindow* New();
  vtkTypeMacro(vtkVoxelGIEGLRenderWindow, vtkGenericOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Which EGL device to render on (index into eglQueryDevicesEXT). Default: 0.
   */
  vtkSetClampMacro(DeviceIndex, int, 0, 64);
  vtkGetMacro(DeviceIndex, int);
  ///@}

  /**
   * Create the EGL context (if not yet) and render.
   */
  void Render() override;

  /**
   * Whether an EGL context could be created; creates it on first call.
   */
  bool CreateContext();

  void MakeCurrent() override;
  bool IsCurrent() override;
  void ReleaseCurrent() override;
  ///@{
  /**
   * Make this window's context current and restore the one current before: GL objects of
   * one window are freed while another renders.
   */
  void PushContext() override;
  void PopContext() override;
  ///@}
  int SupportsOpenGL() override;
  vtkTypeBool IsDirect() override;
  void SetSize(int width, int height) override;
  void Finalize() override;
  void OpenGLInitContext() override;

protected:
  vtkVoxelGIEGLRenderWindow();
  ~vtkVoxelGIEGLRenderWindow() override;

  int DeviceIndex = 0;

private:
  vtkVoxelGIEGLRenderWindow(const vtkVoxelGIEGLRenderWindow&) = delete;
  void operator=(const vtkVoxelGIEGLRenderWindow&) = delete;

  struct EGLState;
  std::unique_ptr<EGLState> EGL;
};

#endif
