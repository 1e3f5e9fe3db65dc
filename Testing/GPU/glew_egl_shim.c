/* Preloaded on headless EGL machines only (LD_PRELOAD): Debian's GLEW 2.2 is built for GLX,
 * so under EGL its glewInit() returns GLEW_ERROR_NO_GLX_DISPLAY (4) after it has loaded every
 * OpenGL entry point, and VTK then logs an error each frame. Report success instead. */
#define _GNU_SOURCE
#include <dlfcn.h>

typedef unsigned int GLenum;

GLenum glewInit(void)
{
  static GLenum (*real)(void) = 0;
  if (!real)
  {
    real = (GLenum(*)(void))dlsym(RTLD_NEXT, "glewInit");
  }
  GLenum result = real();
  return result == 4 ? 0 : result;
}
