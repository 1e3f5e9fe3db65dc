/* A GL call profiler, preloaded (LD_PRELOAD) into a program that renders through VTK: the GPU
 * time of every draw, blit, copy, clear and compute dispatch, from timestamp queries around
 * each call, with the program, framebuffers and viewport it ran with, and the CPU time of
 * each glFinish. A line per call goes to $VOXELGI_GL_PROFILE (default gl-profile.txt) and
 * gl_call_profile.py sums them per kind of work. The queries are read at each glFinish (VTK's
 * volume mapper and the benchmark's frames end with one), so nothing waits that did not.
 * Under EGL preload it before the GLEW shim: "libVoxelGIGLCallProfiler.so:libVoxelGIGlewEGLShim.so".
 * GL 1.1 entry points are wrapped by name; those GLEW loads are wrapped in its function
 * pointers once glewInit has filled them. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef unsigned int GLenum;
typedef unsigned int GLuint;
typedef int GLint;
typedef int GLsizei;
typedef unsigned int GLbitfield;
typedef unsigned long long GLuint64;
#define GL_TIMESTAMP 0x8E28
#define GL_QUERY_RESULT 0x8866
#define GL_CURRENT_PROGRAM 0x8B8D
#define GL_DRAW_FRAMEBUFFER_BINDING 0x8CA6
#define GL_READ_FRAMEBUFFER_BINDING 0x8CAA
#define GL_VIEWPORT 0x0BA2
#define GL_SHADER_SOURCE_LENGTH 0x8B88
#define GL_SHADER_TYPE 0x8B4F
#define GL_FRAGMENT_SHADER 0x8B30
#define GL_COMPUTE_SHADER 0x91B9

typedef struct
{
  const char* Name;
  int Program, Draw, Read, Width, Height, Count;
  GLuint Start, End;
} Call;

#define MAX_CALLS 8192
static Call Calls[MAX_CALLS];
static int CallCount;
static GLuint Queries[2 * MAX_CALLS];
static int HaveQueries;
static FILE* Out;
static unsigned char Described[65536];

static void (*QueryCounter)(GLuint, GLenum);
static void (*GenQueries)(GLsizei, GLuint*);
static void (*GetQueryObjectui64v)(GLuint, GLenum, GLuint64*);
static void (*GetAttachedShaders)(GLuint, GLsizei, GLsizei*, GLuint*);
static void (*GetShaderiv)(GLuint, GLenum, GLint*);
static void (*GetShaderSource)(GLuint, GLsizei, GLsizei*, char*);
static void (*GetIntegerv)(GLenum, GLint*);

/* The function GLEW's pointer `name` holds (null before glewInit). */
static void* GlewFunction(const char* name)
{
  void** pointer = (void**)dlsym(RTLD_DEFAULT, name);
  return pointer ? *pointer : 0;
}

static int Ready(void)
{
  if (!QueryCounter)
  {
    QueryCounter = GlewFunction("__glewQueryCounter");
    GenQueries = GlewFunction("__glewGenQueries");
    GetQueryObjectui64v = GlewFunction("__glewGetQueryObjectui64v");
    GetAttachedShaders = GlewFunction("__glewGetAttachedShaders");
    GetShaderiv = GlewFunction("__glewGetShaderiv");
    GetShaderSource = GlewFunction("__glewGetShaderSource");
    GetIntegerv = dlsym(RTLD_NEXT, "glGetIntegerv");
    const char* path = getenv("VOXELGI_GL_PROFILE");
    Out = fopen(path ? path : "gl-profile.txt", "w");
  }
  return QueryCounter && Out;
}

/* A program's line: which of the words that tell VTK's and the pass's shaders apart its
 * fragment or compute shader holds. */
static void Describe(int program)
{
  if (program <= 0 || program >= 65536 || Described[program])
  {
    return;
  }
  Described[program] = 1;
  static const char* const words[] = { "g_dataPos", "voxelgiBeginRay", "VOXELGI_GBUFFER_IMAGES",
    "voxelgi", "fragOutput0", "local_size_x", "texCoord", 0 };
  GLuint shaders[8];
  GLsizei count = 0;
  GetAttachedShaders(program, 8, &count, shaders);
  for (int i = 0; i < count; ++i)
  {
    GLint type = 0, length = 0;
    GetShaderiv(shaders[i], GL_SHADER_TYPE, &type);
    GetShaderiv(shaders[i], GL_SHADER_SOURCE_LENGTH, &length);
    if (type != GL_FRAGMENT_SHADER && type != GL_COMPUTE_SHADER)
    {
      continue;
    }
    char* source = malloc(length + 1);
    GetShaderSource(shaders[i], length + 1, 0, source);
    fprintf(Out, "PROGRAM %d %d", program, length);
    for (int w = 0; words[w]; ++w)
    {
      if (strstr(source, words[w]))
      {
        fprintf(Out, " %s", words[w]);
      }
    }
    fprintf(Out, "\n");
    free(source);
  }
}

static void Flush(void)
{
  for (int i = 0; i < CallCount; ++i)
  {
    GLuint64 start = 0, end = 0;
    GetQueryObjectui64v(Calls[i].Start, GL_QUERY_RESULT, &start);
    GetQueryObjectui64v(Calls[i].End, GL_QUERY_RESULT, &end);
    fprintf(Out, "CALL %s %d %d %d %d %d %d %.1f\n", Calls[i].Name, Calls[i].Program,
      Calls[i].Draw, Calls[i].Read, Calls[i].Width, Calls[i].Height, Calls[i].Count,
      (end - start) / 1000.0);
  }
  fflush(Out);
  CallCount = 0;
}

static Call* Begin(const char* name, int count)
{
  if (!Ready())
  {
    return 0;
  }
  if (!HaveQueries)
  {
    GenQueries(2 * MAX_CALLS, Queries);
    HaveQueries = 1;
  }
  if (CallCount == MAX_CALLS)
  {
    Flush();
  }
  Call* call = &Calls[CallCount];
  call->Name = name;
  call->Count = count;
  call->Start = Queries[2 * CallCount];
  call->End = Queries[2 * CallCount + 1];
  GLint v[4];
  GetIntegerv(GL_CURRENT_PROGRAM, v);
  call->Program = v[0];
  Describe(v[0]);
  GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, v);
  call->Draw = v[0];
  GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, v);
  call->Read = v[0];
  GetIntegerv(GL_VIEWPORT, v);
  call->Width = v[2];
  call->Height = v[3];
  QueryCounter(call->Start, GL_TIMESTAMP);
  return call;
}

static void End(Call* call)
{
  if (call)
  {
    QueryCounter(call->End, GL_TIMESTAMP);
    ++CallCount;
  }
}

#define WRAP_BY_NAME(name, params, args, count)                                                  \
  void name params                                                                              \
  {                                                                                             \
    static void(*real) params;                                                                  \
    if (!real)                                                                                  \
    {                                                                                           \
      real = dlsym(RTLD_NEXT, #name);                                                           \
    }                                                                                           \
    Call* call = Begin(#name, count);                                                           \
    real args;                                                                                  \
    End(call);                                                                                  \
  }
WRAP_BY_NAME(glDrawArrays, (GLenum m, GLint f, GLsizei c), (m, f, c), c)
WRAP_BY_NAME(glDrawElements, (GLenum m, GLsizei c, GLenum t, const void* i), (m, c, t, i), c)
WRAP_BY_NAME(glClear, (GLbitfield b), (b), (int)b)
WRAP_BY_NAME(glCopyTexSubImage2D,
  (GLenum t, GLint l, GLint x, GLint y, GLint a, GLint b, GLsizei w, GLsizei h),
  (t, l, x, y, a, b, w, h), w)

void glFinish(void)
{
  static void (*real)(void);
  if (!real)
  {
    real = dlsym(RTLD_NEXT, "glFinish");
  }
  struct timespec a, b;
  clock_gettime(CLOCK_MONOTONIC, &a);
  real();
  clock_gettime(CLOCK_MONOTONIC, &b);
  if (Out)
  {
    fprintf(Out, "FINISH %.1f\n", (b.tv_sec - a.tv_sec) * 1e6 + (b.tv_nsec - a.tv_nsec) / 1e3);
    Flush();
  }
}

#define WRAP_POINTER(name, params, args, count)                                                  \
  static void(*Real##name) params;                                                              \
  static void Wrapped##name params                                                              \
  {                                                                                             \
    Call* call = Begin(#name, count);                                                           \
    Real##name args;                                                                            \
    End(call);                                                                                  \
  }
WRAP_POINTER(DrawRangeElements, (GLenum m, GLuint s, GLuint e, GLsizei c, GLenum t, const void* i),
  (m, s, e, c, t, i), c)
WRAP_POINTER(BlitFramebuffer,
  (GLint a, GLint b, GLint c, GLint d, GLint e, GLint f, GLint g, GLint h, GLbitfield m,
    GLenum filter),
  (a, b, c, d, e, f, g, h, m, filter), c - a)
WRAP_POINTER(DispatchCompute, (GLuint x, GLuint y, GLuint z), (x, y, z), (int)(x * y * z))
WRAP_POINTER(DrawArraysInstanced, (GLenum m, GLint f, GLsizei c, GLsizei n), (m, f, c, n), c * n)
WRAP_POINTER(DrawElementsInstanced, (GLenum m, GLsizei c, GLenum t, const void* i, GLsizei n),
  (m, c, t, i, n), c * n)
WRAP_POINTER(ClearTexImage, (GLuint t, GLint l, GLenum f, GLenum type, const void* d),
  (t, l, f, type, d), (int)t)
WRAP_POINTER(MultiDrawElementsIndirect, (GLenum m, GLenum t, const void* i, GLsizei c, GLsizei s),
  (m, t, i, c, s), c)

#define HOOK(name)                                                                               \
  do                                                                                            \
  {                                                                                             \
    void** pointer = (void**)dlsym(RTLD_DEFAULT, "__glew" #name);                               \
    if (pointer && *pointer && *pointer != (void*)Wrapped##name)                                \
    {                                                                                           \
      Real##name = *pointer;                                                                    \
      *pointer = (void*)Wrapped##name;                                                          \
    }                                                                                           \
  } while (0)

GLenum glewInit(void)
{
  static GLenum (*real)(void);
  if (!real)
  {
    real = dlsym(RTLD_NEXT, "glewInit");
  }
  GLenum result = real ? real() : 1;
  HOOK(DrawRangeElements);
  HOOK(BlitFramebuffer);
  HOOK(DispatchCompute);
  HOOK(DrawArraysInstanced);
  HOOK(DrawElementsInstanced);
  HOOK(ClearTexImage);
  HOOK(MultiDrawElementsIndirect);
  return result;
}
