/* Preloaded on headless EGL machines only (LD_PRELOAD): Debian's GLEW 2.2 is built for GLX,
 * so under EGL its glewInit() returns GLEW_ERROR_NO_GLX_DISPLAY (4) after it has loaded every
 * OpenGL entry point, and VTK then logs an error each frame. Report success instead. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>

typedef unsigned int GLenum;
typedef GLenum (*GlewInit)(void);

/* GLEW's own glewInit. RTLD_NEXT finds it when GLEW is in the global scope (a C++ program
 * linked to VTK); Python loads VTK's modules, and with them GLEW, with RTLD_LOCAL, so there
 * it is looked up in the loaded library itself. */
static GlewInit RealGlewInit(void)
{
  GlewInit real = (GlewInit)dlsym(RTLD_NEXT, "glewInit");
  if (!real)
  {
    void* glew = dlopen("libGLEW.so.2.2", RTLD_NOW | RTLD_NOLOAD);
    real = glew ? (GlewInit)dlsym(glew, "glewInit") : 0;
  }
  return real;
}

GLenum glewInit(void)
{
  static GlewInit real = 0;
  if (!real)
  {
    real = RealGlewInit();
  }
  if (!real)
  {
    fprintf(stderr, "libVoxelGIGlewEGLShim: GLEW's glewInit was not found.\n");
    return 1; /* GLEW_ERROR_NO_GL_VERSION: VTK reports that GLEW failed */
  }
  GLenum result = real();
  return result == 4 ? 0 : result;
}
