#include "GLHelpers.h"

#include "VoxelGIShaders.h"

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTextureUnitManager.h"
#include "vtk_glew.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cassert>
#include <fstream>
#include <regex>
#include <cstring>
#include <utility>
#include <vector>

namespace voxelgi
{

//------------------------------------------------------------------------------
namespace
{
/// The info log of a shader or, with `program`, of a program object.
std::string InfoLog(GLuint object, bool program)
{
  GLint length = 0;
  (program ? glGetProgramiv : glGetShaderiv)(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> text(static_cast<std::size_t>(std::max(length, 1)), '\0');
  (program ? glGetProgramInfoLog : glGetShaderInfoLog)(
    object, static_cast<GLsizei>(text.size()), nullptr, text.data());
  return text.data();
}
}

GLProgram::~GLProgram()
{
  // The owner releases GL objects with their context current (ReleaseGraphicsResources).
  assert(!this->IsAllocated());
}

bool GLProgram::Build(
  const std::string& defines, const char* source, std::string& log, const char* fragment)
{
  this->Release();
  const std::string header = "#version 430 core\n" + defines;
  const std::pair<GLenum, const char*> stages[2] = {
    { fragment ? GL_VERTEX_SHADER : GL_COMPUTE_SHADER, source }, { GL_FRAGMENT_SHADER, fragment }
  };
  GLuint program = glCreateProgram();
  for (const auto& stage : stages)
  {
    if (!stage.second)
    {
      continue;
    }
    const char* parts[2] = { header.c_str(), stage.second };
    GLuint shader = glCreateShader(stage.first);
    glShaderSource(shader, 2, parts, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok)
    {
      log = NameShaderFiles(InfoLog(shader, false));
      glDeleteShader(shader);
      glDeleteProgram(program);
      return false;
    }
    glAttachShader(program, shader);
    glDeleteShader(shader); // freed with the program
  }
  glLinkProgram(program);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok)
  {
    log = InfoLog(program, true);
    glDeleteProgram(program);
    return false;
  }
  this->Handle = program;
  this->Defines = defines;
  return true;
}

bool GLProgram::BuildOnce(const char* source, const char* what, std::string& error,
  const std::string& defines, const char* fragment)
{
  std::string log;
  if ((this->IsReady() && this->Defines == defines) ||
    this->Build(defines, source, log, fragment))
  {
    return true;
  }
  error = std::string(what) + " shader failed to build: " + log;
  return false;
}

void GLProgram::Use(vtkOpenGLRenderWindow* renWin)
{
  renWin->GetShaderCache()->ReleaseCurrentShader();
  glUseProgram(this->Handle);
}

void GLProgram::SetInt(const char* name, int value)
{
  glUniform1i(glGetUniformLocation(this->Handle, name), value);
}

void GLProgram::SetUInt(const char* name, unsigned int value)
{
  glUniform1ui(glGetUniformLocation(this->Handle, name), value);
}

void GLProgram::SetFloat(const char* name, float value)
{
  glUniform1f(glGetUniformLocation(this->Handle, name), value);
}

void GLProgram::SetVec3Array(const char* name, int count, const float* values)
{
  glUniform3fv(glGetUniformLocation(this->Handle, name), count, values);
}

void GLProgram::SetVec2(const char* name, float x, float y)
{
  glUniform2f(glGetUniformLocation(this->Handle, name), x, y);
}

void GLProgram::SetIVec2(const char* name, int x, int y)
{
  glUniform2i(glGetUniformLocation(this->Handle, name), x, y);
}

void GLProgram::SetVec4(const char* name, const float* values)
{
  glUniform4fv(glGetUniformLocation(this->Handle, name), 1, values);
}

void GLProgram::SetMat3(const char* name, const float* values)
{
  glUniformMatrix3fv(glGetUniformLocation(this->Handle, name), 1, GL_FALSE, values);
}

void GLProgram::SetMat4Array(const char* name, int count, const float* values)
{
  glUniformMatrix4fv(glGetUniformLocation(this->Handle, name), count, GL_FALSE, values);
}

void GLProgram::DispatchCube(int n, int localSize)
{
  const GLuint groups = static_cast<GLuint>((n + localSize - 1) / localSize);
  glDispatchCompute(groups, groups, groups);
  glUseProgram(0);
}

void GLProgram::DispatchGroups(unsigned int x, unsigned int y, unsigned int z)
{
  glDispatchCompute(x, y, z);
  glUseProgram(0);
}

void GLProgram::DispatchIndirect(const StorageBuffer& arguments, std::size_t offset)
{
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, arguments.GetHandle());
  glDispatchComputeIndirect(static_cast<GLintptr>(offset));
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glUseProgram(0);
}

void GLProgram::DispatchImage(int width, int height, int tile)
{
  glDispatchCompute(static_cast<GLuint>((width + tile - 1) / tile),
    static_cast<GLuint>((height + tile - 1) / tile), 1);
  glUseProgram(0);
}

void GLProgram::Release()
{
  if (this->Handle)
  {
    glDeleteProgram(this->Handle);
    this->Handle = 0;
  }
}

//------------------------------------------------------------------------------
namespace
{
std::size_t BytesPerTexel(GLenum internalFormat)
{
  switch (internalFormat)
  {
    case GL_R8UI:
      return 1;
    case GL_RGBA8:
    case GL_R32UI:
    case GL_R32F:
    case GL_R11F_G11F_B10F:
      return 4;
    case GL_RGBA16F:
      return 8;
    case GL_RGBA32F:
      return 16;
    default:
      return 4;
  }
}
}

Volume3D::~Volume3D()
{
  // The owner releases GL objects with their context current (ReleaseGraphicsResources).
  assert(!this->IsAllocated());
}

bool Volume3D::Allocate(unsigned int internalFormat, int resolution, int levels)
{
  if (this->Handle && this->Format == internalFormat && this->Size == resolution &&
    this->LevelCount == levels)
  {
    return true;
  }
  this->Release();
  ClearErrors(); // so the check below reports this allocation only
  glGenTextures(1, &this->Handle);
  glBindTexture(GL_TEXTURE_3D, this->Handle);
  glTexStorage3D(GL_TEXTURE_3D, levels, internalFormat, resolution, resolution, resolution);
  const bool integer = internalFormat == GL_R8UI || internalFormat == GL_R32UI;
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER,
    integer ? GL_NEAREST : (levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR));
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAX_LEVEL, levels - 1);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, integer ? GL_NEAREST : GL_LINEAR);
  // Clamp to the edge texels: a transparent border would dilute coarse samples of geometry
  // near the grid's faces (rays and cones stop at the grid themselves).
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_3D, 0);
  if (glGetError() != GL_NO_ERROR)
  {
    this->Release();
    return false;
  }
  this->Format = internalFormat;
  this->Size = resolution;
  this->LevelCount = levels;
  this->ByteSize = StorageBytes(internalFormat, resolution, levels);
  return true;
}

std::size_t Volume3D::StorageBytes(unsigned int internalFormat, int resolution, int levels)
{
  std::size_t bytes = 0;
  for (int level = 0; level < levels; ++level)
  {
    const std::size_t n = static_cast<std::size_t>(std::max(resolution >> level, 1));
    bytes += n * n * n * BytesPerTexel(internalFormat);
  }
  return bytes;
}

void Volume3D::BindImage(unsigned int unit, unsigned int access, int level) const
{
  glBindImageTexture(unit, this->Handle, level, GL_TRUE, 0, access, this->Format);
}

void Volume3D::GenerateMipmaps() const
{
  glBindTexture(GL_TEXTURE_3D, this->Handle);
  glGenerateMipmap(GL_TEXTURE_3D);
  glBindTexture(GL_TEXTURE_3D, 0);
}

int Volume3D::BindSampler(vtkOpenGLRenderWindow* renWin) const
{
  const int unit = renWin->GetTextureUnitManager()->Allocate();
  if (unit >= 0)
  {
    // Through VTK's state cache, which tracks the active unit.
    renWin->GetState()->vtkglActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_3D, this->Handle);
  }
  return unit;
}

void Volume3D::Read(unsigned int format, unsigned int type, void* data) const
{
  glBindTexture(GL_TEXTURE_3D, this->Handle);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_3D, 0, format, type, data);
  glBindTexture(GL_TEXTURE_3D, 0);
}

void Volume3D::Upload(unsigned int format, unsigned int type, const void* data) const
{
  glBindTexture(GL_TEXTURE_3D, this->Handle);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage3D(
    GL_TEXTURE_3D, 0, 0, 0, 0, this->Size, this->Size, this->Size, format, type, data);
  glBindTexture(GL_TEXTURE_3D, 0);
}

void Volume3D::Clear() const
{
  glClearTexImage(this->Handle, 0, GL_RGBA, GL_FLOAT, nullptr); // null: zero
}

void Volume3D::Release()
{
  if (this->Handle)
  {
    glDeleteTextures(1, &this->Handle);
    this->Handle = 0;
  }
  this->Format = 0;
  this->Size = 0;
  this->LevelCount = 0;
  this->ByteSize = 0;
}

//------------------------------------------------------------------------------
SamplerBindings::~SamplerBindings()
{
  for (int i = this->Count - 1; i >= 0; --i)
  {
    this->Window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(this->Units[i]));
    glBindTexture(this->Targets[i], 0);
    this->Window->GetTextureUnitManager()->Free(this->Units[i]);
  }
}

int SamplerBindings::Keep(int unit, unsigned int target)
{
  if (unit >= 0 && this->Count < 16)
  {
    this->Units[this->Count] = unit;
    this->Targets[this->Count++] = target;
  }
  else
  {
    this->Failed = true;
  }
  return unit;
}

int SamplerBindings::Add(const Volume3D& volume)
{
  return this->Keep(volume.BindSampler(this->Window), GL_TEXTURE_3D);
}

int SamplerBindings::Add(const ShadowMapArray& maps)
{
  return this->AddTexture(maps.GetTexture(), GL_TEXTURE_2D_ARRAY);
}

int SamplerBindings::AddTexture(unsigned int texture, unsigned int target)
{
  const int unit = this->Window->GetTextureUnitManager()->Allocate();
  if (unit >= 0)
  {
    this->Window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(target, texture);
  }
  return this->Keep(unit, target);
}

//------------------------------------------------------------------------------
StorageBuffer::~StorageBuffer()
{
  // The owner releases GL objects with their context current (ReleaseGraphicsResources).
  assert(!this->IsAllocated());
}

bool StorageBuffer::Allocate(std::size_t bytes)
{
  if (this->Handle && this->ByteSize == bytes)
  {
    return true;
  }
  this->Release();
  ClearErrors();
  glGenBuffers(1, &this->Handle);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Handle);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_DYNAMIC_COPY);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  if (glGetError() != GL_NO_ERROR)
  {
    this->Release();
    return false;
  }
  this->ByteSize = bytes;
  return true;
}

void StorageBuffer::Bind(unsigned int index) const
{
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, index, this->Handle);
}

void StorageBuffer::BindUniform(unsigned int index) const
{
  glBindBufferBase(GL_UNIFORM_BUFFER, index, this->Handle);
}

void StorageBuffer::Upload(const void* data, std::size_t bytes) const
{
  glBindBuffer(GL_UNIFORM_BUFFER, this->Handle);
  glBufferSubData(GL_UNIFORM_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data);
  glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

void StorageBuffer::Read(std::size_t offset, std::size_t bytes, void* data) const
{
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Handle);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, static_cast<GLintptr>(offset),
    static_cast<GLsizeiptr>(bytes), data);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

void StorageBuffer::Release()
{
  if (this->Handle)
  {
    glDeleteBuffers(1, &this->Handle);
    this->Handle = 0;
  }
  this->ByteSize = 0;
}

//------------------------------------------------------------------------------
ShadowMapArray::~ShadowMapArray()
{
  // The owner releases GL objects with their context current (ReleaseGraphicsResources).
  assert(!this->IsAllocated());
}

bool ShadowMapArray::Allocate(int size, int layers)
{
  if (this->Texture && this->Resolution == size && this->LayerCount == layers)
  {
    return true;
  }
  this->Release();
  ClearErrors();
  glGenTextures(1, &this->Texture);
  glBindTexture(GL_TEXTURE_2D_ARRAY, this->Texture);
  glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_DEPTH_COMPONENT32F, size, size, layers);
  // Hardware percentage-closer filtering: linear filtering of the depth comparison.
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  glGenFramebuffers(1, &this->Framebuffer);
  if (glGetError() != GL_NO_ERROR)
  {
    this->Release();
    return false;
  }
  this->Resolution = size;
  this->LayerCount = layers;
  return true;
}

unsigned int ShadowMapArray::PrepareLayer(int layer)
{
  GLint previous = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, this->Framebuffer);
  glFramebufferTextureLayer(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, this->Texture, 0, layer);
  glDrawBuffer(GL_NONE);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(previous));
  return this->Framebuffer;
}

std::size_t ShadowMapArray::Bytes() const
{
  return static_cast<std::size_t>(this->Resolution) * this->Resolution * this->LayerCount * 4;
}

void ShadowMapArray::Release()
{
  if (this->Texture)
  {
    glDeleteTextures(1, &this->Texture);
    this->Texture = 0;
  }
  if (this->Framebuffer)
  {
    glDeleteFramebuffers(1, &this->Framebuffer);
    this->Framebuffer = 0;
  }
  this->Resolution = this->LayerCount = 0;
}

//------------------------------------------------------------------------------
EmptyFramebuffer::~EmptyFramebuffer()
{
  // The owner releases GL objects with their context current (ReleaseGraphicsResources).
  assert(!this->IsAllocated());
}

unsigned int EmptyFramebuffer::Prepare(int width, int height)
{
  if (!this->Handle)
  {
    glGenFramebuffers(1, &this->Handle);
  }
  if (this->Width != width || this->Height != height)
  {
    GLint previous = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, this->Handle);
    glFramebufferParameteri(GL_DRAW_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_WIDTH, width);
    glFramebufferParameteri(GL_DRAW_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_HEIGHT, height);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(previous));
    this->Width = width;
    this->Height = height;
  }
  return this->Handle;
}

void EmptyFramebuffer::Release()
{
  if (this->Handle)
  {
    glDeleteFramebuffers(1, &this->Handle);
    this->Handle = 0;
  }
  this->Width = this->Height = 0;
}

//------------------------------------------------------------------------------
StageTimer::~StageTimer()
{
  // The owner releases GL objects with their context current (ReleaseGraphicsResources).
  assert(!this->IsAllocated());
}

void StageTimer::Begin()
{
  if (!this->Queries[0])
  {
    glGenQueries(2, this->Queries);
  }
  glQueryCounter(this->Queries[0], GL_TIMESTAMP);
}

void StageTimer::End()
{
  glQueryCounter(this->Queries[1], GL_TIMESTAMP);
  this->Pending = true;
}

double StageTimer::Milliseconds()
{
  if (!this->Pending)
  {
    return 0.0;
  }
  GLuint64 begin = 0, end = 0;
  glGetQueryObjectui64v(this->Queries[0], GL_QUERY_RESULT, &begin);
  glGetQueryObjectui64v(this->Queries[1], GL_QUERY_RESULT, &end);
  this->Pending = false;
  return end > begin ? static_cast<double>(end - begin) * 1e-6 : 0.0;
}

void StageTimer::Release()
{
  if (this->Queries[0])
  {
    glDeleteQueries(2, this->Queries);
    this->Queries[0] = this->Queries[1] = 0;
  }
  this->Pending = false;
}

//------------------------------------------------------------------------------
std::string ImageSizeError(const char* what, int width, int height)
{
  GLint texture = 0;
  GLint framebuffer[2] = { 0, 0 };
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, framebuffer);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, framebuffer + 1);
  const int size[2] = { width, height };
  for (int axis = 0; axis < 2; ++axis)
  {
    // The images are textures and framebuffer attachments: the smaller limit applies.
    const bool byFramebuffer = framebuffer[axis] > 0 && framebuffer[axis] < texture;
    const GLint limit = byFramebuffer ? framebuffer[axis] : texture;
    if (limit > 0 && size[axis] > limit)
    {
      const char* name = !byFramebuffer ? "GL_MAX_TEXTURE_SIZE"
        : axis == 0                     ? "GL_MAX_FRAMEBUFFER_WIDTH"
                                        : "GL_MAX_FRAMEBUFFER_HEIGHT";
      return std::string(what) + " is " + std::to_string(width) + " x " +
        std::to_string(height) + " pixels, larger than this OpenGL's " + name + " " +
        std::to_string(limit) + " (its images cannot be allocated)";
    }
  }
  return std::string();
}

bool MakeCurrentForReading(vtkOpenGLRenderWindow* window)
{
  window->MakeCurrent();
  return window->IsCurrent();
}

void StoredSize(vtkTextureObject* texture, int& width, int& height)
{
  GLint w = 0, h = 0;
  texture->Activate();
  glGetTexLevelParameteriv(texture->GetTarget(), 0, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(texture->GetTarget(), 0, GL_TEXTURE_HEIGHT, &h);
  texture->Deactivate();
  width = w;
  height = h;
}

void ContextVersion(int& major, int& minor)
{
  GLint values[2] = { 0, 0 };
  glGetIntegerv(GL_MAJOR_VERSION, values);
  glGetIntegerv(GL_MINOR_VERSION, values + 1);
  major = values[0];
  minor = values[1];
}

std::string RendererName()
{
  const GLubyte* name = glGetString(GL_RENDERER);
  return name ? reinterpret_cast<const char*>(name) : "";
}

bool HasExtension(const char* name)
{
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i)
  {
    const char* extension = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
    if (extension && std::strcmp(extension, name) == 0)
    {
      return true;
    }
  }
  return false;
}

namespace
{
/// A "Key: N kB" line of /proc/meminfo, in bytes (-1: absent).
long long MemInfoBytes(const char* key)
{
  std::ifstream meminfo("/proc/meminfo");
  std::string name;
  long long kib = 0;
  std::string unit;
  while (meminfo >> name >> kib)
  {
    std::getline(meminfo, unit);
    if (name == key)
    {
      return kib * 1024;
    }
  }
  return -1;
}

/// Address space the process may still map under its RLIMIT_AS (-1: unlimited or unknown).
long long AddressSpaceLeft()
{
  struct rlimit limit;
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
  {
    return -1;
  }
  std::ifstream statm("/proc/self/statm");
  long long pages = 0;
  if (!(statm >> pages))
  {
    return -1;
  }
  const long long used = pages * sysconf(_SC_PAGESIZE);
  return std::max(static_cast<long long>(limit.rlim_cur) - used, 0LL);
}
}

long long AvailableMemory(std::string& source)
{
  if (HasExtension("GL_NVX_gpu_memory_info"))
  {
    GLint kib = 0;
    glGetIntegerv(0x9049 /* GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX */, &kib);
    source = "free video memory, GL_NVX_gpu_memory_info";
    return static_cast<long long>(kib) * 1024;
  }
  if (HasExtension("GL_ATI_meminfo"))
  {
    GLint kib[4] = { 0, 0, 0, 0 };
    glGetIntegerv(0x87FC /* GL_TEXTURE_FREE_MEMORY_ATI */, kib);
    source = "free texture memory, GL_ATI_meminfo";
    return static_cast<long long>(kib[0]) * 1024;
  }
  const long long host = MemInfoBytes("MemAvailable:");
  const long long address = AddressSpaceLeft();
  if (address >= 0 && (host < 0 || address < host))
  {
    source = "address space left under the process's RLIMIT_AS";
    return address;
  }
  source = "available host memory";
  return host;
}

//------------------------------------------------------------------------------
void BindImage2D(
  unsigned int unit, vtkTextureObject* texture, unsigned int access, unsigned int format)
{
  glBindImageTexture(unit, texture->GetHandle(), 0, GL_FALSE, 0, access, format);
}

unsigned int DescribeAttachment(int framebuffer, unsigned int attachment, int description[5])
{
  GLint type = GL_NONE, name = 0;
  glGetNamedFramebufferAttachmentParameteriv(
    framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  glGetNamedFramebufferAttachmentParameteriv(
    framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
  description[0] = name;
  if (type == GL_RENDERBUFFER)
  {
    glGetNamedRenderbufferParameteriv(name, GL_RENDERBUFFER_INTERNAL_FORMAT, description + 1);
    glGetNamedRenderbufferParameteriv(name, GL_RENDERBUFFER_SAMPLES, description + 2);
    glGetNamedRenderbufferParameteriv(name, GL_RENDERBUFFER_WIDTH, description + 3);
    glGetNamedRenderbufferParameteriv(name, GL_RENDERBUFFER_HEIGHT, description + 4);
    return GL_RENDERBUFFER;
  }
  if (type != GL_TEXTURE)
  {
    return GL_NONE;
  }
  GLint level = 0, layered = GL_FALSE, target = GL_NONE;
  glGetNamedFramebufferAttachmentParameteriv(
    framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &level);
  glGetNamedFramebufferAttachmentParameteriv(
    framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_LAYERED, &layered);
  glGetTextureParameteriv(name, GL_TEXTURE_TARGET, &target);
  if (level != 0 || layered || (target != GL_TEXTURE_2D && target != GL_TEXTURE_2D_MULTISAMPLE))
  {
    return GL_NONE;
  }
  glGetTextureLevelParameteriv(name, 0, GL_TEXTURE_INTERNAL_FORMAT, description + 1);
  glGetTextureLevelParameteriv(name, 0, GL_TEXTURE_SAMPLES, description + 2);
  glGetTextureLevelParameteriv(name, 0, GL_TEXTURE_WIDTH, description + 3);
  glGetTextureLevelParameteriv(name, 0, GL_TEXTURE_HEIGHT, description + 4);
  return GL_TEXTURE;
}

bool DescribeDrawTarget(
  int& framebuffer, int& buffer, int color[5], int depth[5], unsigned int types[2])
{
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
  glGetIntegerv(GL_DRAW_BUFFER0, &buffer);
  if (framebuffer == 0 || buffer < GL_COLOR_ATTACHMENT0 || buffer > GL_COLOR_ATTACHMENT15)
  {
    return false;
  }
  types[0] = DescribeAttachment(framebuffer, static_cast<unsigned int>(buffer), color);
  types[1] = DescribeAttachment(framebuffer, GL_DEPTH_ATTACHMENT, depth);
  return true;
}

ScopedTextures::ScopedTextures(std::initializer_list<vtkTextureObject*> textures)
{
  for (vtkTextureObject* texture : textures)
  {
    if (texture && this->Count < 8)
    {
      texture->Activate();
      this->Textures[this->Count++] = texture;
      this->Failed = this->Failed || texture->GetTextureUnit() < 0;
    }
  }
}

ScopedTextures::~ScopedTextures()
{
  while (this->Count > 0)
  {
    this->Textures[--this->Count]->Deactivate();
  }
}

//------------------------------------------------------------------------------
vtkShaderProgram* ReadyQuad(
  std::unique_ptr<vtkOpenGLQuadHelper>& quad, vtkOpenGLRenderWindow* renWin, const char* fragment)
{
  if (!quad)
  {
    quad.reset(new vtkOpenGLQuadHelper(renWin,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fragment, ""));
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  return (quad->Program && quad->Program->GetCompiled()) ? quad->Program : nullptr;
}

vtkSmartPointer<vtkTextureObject> NewImageTexture(vtkOpenGLRenderWindow* renWin,
  int internalFormat, int width, int height, int components)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(renWin);
  texture->SetInternalFormat(internalFormat);
  texture->SetFormat(components == 1 ? GL_RED : components == 2 ? GL_RG : GL_RGBA);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->Allocate2D(width, height, components, VTK_FLOAT);
  return texture;
}

//------------------------------------------------------------------------------
int ClearErrors()
{
  int count = 0;
  while (glGetError() != GL_NO_ERROR && count < 64)
  {
    ++count;
  }
  return count;
}

std::string NameShaderFiles(const std::string& log)
{
  // Compilers start messages with "<file>:<line>" (Mesa) or "<file>(<line>)" (NVIDIA).
  static const std::regex location(R"((^|\n)(\d+)([:(]\d+))");
  std::string named;
  auto begin = log.cbegin();
  for (std::sregex_iterator it(log.begin(), log.end(), location), end; it != end; ++it)
  {
    const int file = std::stoi((*it)[2].str());
    named.append(begin, (*it)[2].first);
    named += file >= 0 && file < shaders::file_count ? shaders::file_names[file] : (*it)[2].str();
    begin = (*it)[2].second;
  }
  named.append(begin, log.cend());
  return named;
}

}
