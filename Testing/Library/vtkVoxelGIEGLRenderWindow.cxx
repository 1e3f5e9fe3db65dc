#include "vtkVoxelGIEGLRenderWindow.h"

#include "vtkObjectFactory.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkVoxelGIEGLRenderWindow);

struct vtkVoxelGIEGLRenderWindow::EGLState
{
  EGLDisplay Display = EGL_NO_DISPLAY;
  EGLConfig Config = nullptr;
  EGLContext Context = EGL_NO_CONTEXT;
  EGLSurface Surface = EGL_NO_SURFACE;
  int SurfaceSize[2] = { 0, 0 };
  bool Failed = false;
  bool GlewReported = false;
  struct Current
  {
    EGLDisplay Display;
    EGLSurface Draw, Read;
    EGLContext Context;
  };
  std::vector<Current> Pushed;

  EGLDisplay OpenDisplay(int device)
  {
    auto queryDevices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto platformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (queryDevices && platformDisplay)
    {
      EGLDeviceEXT devices[64];
      EGLint count = 0;
      if (queryDevices(64, devices, &count) && device < count)
      {
        EGLDisplay display = platformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[device], nullptr);
        if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr))
        {
          return display;
        }
      }
    }
    EGLDisplay display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    return (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) ? display
                                                                                    : EGL_NO_DISPLAY;
  }

  bool MakeSurface(int width, int height)
  {
    if (this->Surface != EGL_NO_SURFACE)
    {
      eglMakeCurrent(this->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroySurface(this->Display, this->Surface);
    }
    const EGLint attributes[] = { EGL_WIDTH, std::max(width, 1), EGL_HEIGHT, std::max(height, 1),
      EGL_NONE };
    this->Surface = eglCreatePbufferSurface(this->Display, this->Config, attributes);
    this->SurfaceSize[0] = width;
    this->SurfaceSize[1] = height;
    return this->Surface != EGL_NO_SURFACE &&
      eglMakeCurrent(this->Display, this->Surface, this->Surface, this->Context);
  }
};

vtkVoxelGIEGLRenderWindow::vtkVoxelGIEGLRenderWindow()
  : EGL(new EGLState)
{
  this->SetOwnContext(true);
}

vtkVoxelGIEGLRenderWindow::~vtkVoxelGIEGLRenderWindow()
{
  this->Finalize();
  EGLState& egl = *this->EGL;
  if (egl.Display != EGL_NO_DISPLAY)
  {
    eglMakeCurrent(egl.Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (egl.Context != EGL_NO_CONTEXT)
    {
      eglDestroyContext(egl.Display, egl.Context);
    }
    if (egl.Surface != EGL_NO_SURFACE)
    {
      eglDestroySurface(egl.Display, egl.Surface);
    }
  }
}

bool vtkVoxelGIEGLRenderWindow::CreateContext()
{
  EGLState& egl = *this->EGL;
  if (egl.Context != EGL_NO_CONTEXT || egl.Failed)
  {
    return !egl.Failed;
  }
  egl.Failed = true;
  egl.Display = egl.OpenDisplay(this->DeviceIndex);
  if (egl.Display == EGL_NO_DISPLAY)
  {
    vtkErrorMacro(<< "No EGL display could be opened.");
    return false;
  }
  const EGLint configAttributes[] = { EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
    EGL_OPENGL_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
    EGL_DEPTH_SIZE, 24, EGL_NONE };
  EGLint count = 0;
  if (!eglChooseConfig(egl.Display, configAttributes, &egl.Config, 1, &count) || count < 1 ||
    !eglBindAPI(EGL_OPENGL_API))
  {
    vtkErrorMacro(<< "No EGL configuration for desktop OpenGL with a pbuffer.");
    return false;
  }
  const EGLint contextAttributes[] = { EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
    EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
  egl.Context = eglCreateContext(egl.Display, egl.Config, EGL_NO_CONTEXT, contextAttributes);
  if (egl.Context == EGL_NO_CONTEXT)
  {
    vtkErrorMacro(<< "Could not create an OpenGL 4.5 core context through EGL.");
    return false;
  }
  const int* size = this->GetSize();
  if (!egl.MakeSurface(size[0], size[1]))
  {
    vtkErrorMacro(<< "Could not create or bind an EGL pbuffer surface.");
    return false;
  }
  egl.Failed = false;
  this->SetReadyForRendering(true);
  this->SetMapped(1);
  this->InitializeFromCurrentContext();
  return true;
}

void vtkVoxelGIEGLRenderWindow::Render()
{
  if (!this->CreateContext())
  {
    return;
  }
  this->MakeCurrent();
  if (!this->IsCurrent())
  {
    vtkErrorMacro(<< "The window's EGL context could not be made current: it is current in "
                     "another thread; call ReleaseCurrent() there first. Nothing is rendered.");
    return;
  }
  this->Superclass::Render();
}

void vtkVoxelGIEGLRenderWindow::MakeCurrent()
{
  EGLState& egl = *this->EGL;
  if (egl.Context != EGL_NO_CONTEXT)
  {
    eglMakeCurrent(egl.Display, egl.Surface, egl.Surface, egl.Context);
  }
}

bool vtkVoxelGIEGLRenderWindow::IsCurrent()
{
  return this->EGL->Context != EGL_NO_CONTEXT && eglGetCurrentContext() == this->EGL->Context;
}

void vtkVoxelGIEGLRenderWindow::ReleaseCurrent()
{
  if (this->IsCurrent())
  {
    eglMakeCurrent(this->EGL->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
}

void vtkVoxelGIEGLRenderWindow::PushContext()
{
  this->EGL->Pushed.push_back({ eglGetCurrentDisplay(), eglGetCurrentSurface(EGL_DRAW),
    eglGetCurrentSurface(EGL_READ), eglGetCurrentContext() });
  if (!this->IsCurrent())
  {
    this->MakeCurrent();
  }
}

void vtkVoxelGIEGLRenderWindow::PopContext()
{
  EGLState& egl = *this->EGL;
  if (egl.Pushed.empty())
  {
    return;
  }
  const EGLState::Current before = egl.Pushed.back();
  egl.Pushed.pop_back();
  if (before.Context == eglGetCurrentContext())
  {
    return;
  }
  if (before.Context == EGL_NO_CONTEXT)
  {
    this->ReleaseCurrent();
  }
  else
  {
    eglMakeCurrent(before.Display, before.Draw, before.Read, before.Context);
  }
}

int vtkVoxelGIEGLRenderWindow::SupportsOpenGL()
{
  return this->CreateContext() ? 1 : 0;
}

vtkTypeBool vtkVoxelGIEGLRenderWindow::IsDirect()
{
  return 1;
}

void vtkVoxelGIEGLRenderWindow::SetSize(int width, int height)
{
  this->Superclass::SetSize(width, height);
  EGLState& egl = *this->EGL;
  // The pbuffer only ever grows: VTK renders into its own framebuffers of the window size.
  if (egl.Context != EGL_NO_CONTEXT &&
    (width > egl.SurfaceSize[0] || height > egl.SurfaceSize[1]))
  {
    egl.MakeSurface(std::max(width, egl.SurfaceSize[0]), std::max(height, egl.SurfaceSize[1]));
  }
}

void vtkVoxelGIEGLRenderWindow::Finalize()
{
  if (this->EGL && this->EGL->Context != EGL_NO_CONTEXT)
  {
    this->MakeCurrent();
    this->ReleaseGraphicsResources(this);
  }
}

void vtkVoxelGIEGLRenderWindow::OpenGLInitContext()
{
  // VTK retries (and reports) a failed glewInit at every render; after the first report
  // the retries are quiet.
  const int display = vtkObject::GetGlobalWarningDisplay();
  vtkObject::SetGlobalWarningDisplay(this->EGL->GlewReported ? 0 : display);
  this->Superclass::OpenGLInitContext();
  vtkObject::SetGlobalWarningDisplay(display);
  if (!this->Initialized && !this->EGL->GlewReported)
  {
    this->EGL->GlewReported = true;
    vtkWarningMacro(<< "GLEW, built for GLX, reports an error under EGL although OpenGL works; "
                       "preload libVoxelGIGlewEGLShim.so (LD_PRELOAD) to initialize it. Not "
                       "said again for this window.");
  }
}

void vtkVoxelGIEGLRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DeviceIndex: " << this->DeviceIndex << "\n";
  os << indent << "Context: " << (this->EGL->Context != EGL_NO_CONTEXT ? "created" : "none")
     << "\n";
}
