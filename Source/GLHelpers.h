/**
 * Internal GL helpers of the VoxelGI stages: compute programs, 3D volumes with immutable
 * storage and image binding, shader storage buffers, an attachment-less framebuffer and
 * timer queries. The only place raw GL object boilerplate lives.
 *
 * All functions expect the render window's context to be current. Raw program binds are
 * reported to VTK's shader cache so its notion of the bound program stays right.
 *
 * One release rule: a GL object is freed only by Release(), called from its stage's
 * ReleaseGraphicsResources(vtkWindow*) with that window's context current. Destructors do
 * not touch GL (whatever context is current then may not own the object); they check that
 * the object was released.
 */
#ifndef VoxelGIGLHelpers_h
#define VoxelGIGLHelpers_h

#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <string>

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;

namespace voxelgi
{
class StorageBuffer;

/// A GL program: one compute shader, or a vertex and a fragment shader, each built from one
/// GLSL source (the `#version` line and the defines are prepended).
class GLProgram
{
public:
  GLProgram() = default;
  ~GLProgram();
  GLProgram(const GLProgram&) = delete;
  GLProgram& operator=(const GLProgram&) = delete;

  /// Compile and link `defines` + `source` as a compute shader, or with a `fragment` source
  /// as a vertex and a fragment shader; on failure returns false and fills `log`.
  bool Build(const std::string& defines, const char* source, std::string& log,
    const char* fragment = nullptr);
  /// Build `defines` + `source` (and `fragment`, as in Build) unless the program is ready
  /// with those defines; on failure `error` says that the `what` shader failed, with the
  /// compiler's log.
  bool BuildOnce(const char* source, const char* what, std::string& error,
    const std::string& defines = "", const char* fragment = nullptr);
  bool IsReady() const { return this->Handle != 0; }
  bool IsAllocated() const { return this->Handle != 0; }

  /// Bind the program (after telling VTK's shader cache to forget its current program).
  void Use(vtkOpenGLRenderWindow* renWin);
  void SetInt(const char* name, int value);
  void SetUInt(const char* name, unsigned int value);
  void SetFloat(const char* name, float value);
  void SetVec3Array(const char* name, int count, const float* values);
  void SetVec2(const char* name, float x, float y);
  void SetIVec2(const char* name, int x, int y);
  void SetVec4(const char* name, const float* values);
  /// Column-major 4x4 matrices.
  void SetMat4Array(const char* name, int count, const float* values);
  /// A column-major 3x3 matrix.
  void SetMat3(const char* name, const float* values);
  /// Dispatch enough groups of `localSize`^3 to cover `n`^3 invocations, then unbind.
  void DispatchCube(int n, int localSize);
  /// Dispatch tiles of `tile` x `tile` to cover a `width` x `height` image, then unbind.
  void DispatchImage(int width, int height, int tile);
  /// Dispatch `x` x `y` x `z` groups, then unbind.
  void DispatchGroups(unsigned int x, unsigned int y, unsigned int z);
  /// Dispatch the groups that three uints of a buffer count (written on the GPU, e.g. the
  /// occupied-brick list), at `offset` bytes, then unbind.
  void DispatchIndirect(const StorageBuffer& arguments, std::size_t offset = 0);
  void Release();

private:
  unsigned int Handle = 0;
  std::string Defines; // of the ready program
};

/// A 3D texture with immutable storage, usable as sampler and as image.
class Volume3D
{
public:
  Volume3D() = default;
  ~Volume3D();
  Volume3D(const Volume3D&) = delete;
  Volume3D& operator=(const Volume3D&) = delete;

  /// (Re)allocate `resolution`^3 texels of `internalFormat` with `levels` mip levels.
  bool Allocate(unsigned int internalFormat, int resolution, int levels = 1);
  /// The bytes such an allocation holds.
  static std::size_t StorageBytes(unsigned int internalFormat, int resolution, int levels = 1);
  bool IsAllocated() const { return this->Handle != 0; }
  int Levels() const { return this->LevelCount; }
  void BindImage(unsigned int unit, unsigned int access, int level = 0) const;
  /// Box-filter the mip chain from level 0.
  void GenerateMipmaps() const;
  /// Bind for sampling on a unit taken from the window's texture unit manager.
  int BindSampler(vtkOpenGLRenderWindow* renWin) const;
  /// Read level 0 back into `data`, which must hold Bytes() for the given format/type.
  void Read(unsigned int format, unsigned int type, void* data) const;
  /// Replace level 0 with `data`, given in `format`/`type`.
  void Upload(unsigned int format, unsigned int type, const void* data) const;
  /// Set level 0 to zero (a float or normalized format).
  void Clear() const;
  std::size_t Bytes() const { return this->ByteSize; }
  int Resolution() const { return this->Size; }
  void Release();

private:
  unsigned int Handle = 0;
  unsigned int Format = 0;
  int Size = 0;
  int LevelCount = 0;
  std::size_t ByteSize = 0;
};

class ShadowMapArray;

/**
 * Sampler bindings for one draw or dispatch: each Add() takes a texture unit from the
 * window's texture unit manager (so VTK's own textures are never disturbed), binds the
 * volume there and returns the unit; the destructor gives the units back.
 */
class SamplerBindings
{
public:
  explicit SamplerBindings(vtkOpenGLRenderWindow* renWin)
    : Window(renWin)
  {
  }
  ~SamplerBindings();
  SamplerBindings(const SamplerBindings&) = delete;
  SamplerBindings& operator=(const SamplerBindings&) = delete;

  int Add(const Volume3D& volume);
  int Add(const ShadowMapArray& maps);
  /// Bind the texture named `texture`, whose target is `target` (e.g. GL_TEXTURE_2D_ARRAY).
  int AddTexture(unsigned int texture, unsigned int target);
  /// False when a unit could not be had (the window's units are all taken): a dispatch
  /// would then sample whatever the program's stale sampler uniforms point at; skip it.
  bool Complete() const { return !this->Failed; }

private:
  int Keep(int unit, unsigned int target);

  vtkOpenGLRenderWindow* Window;
  int Units[16];
  unsigned int Targets[16];
  int Count = 0;
  bool Failed = false;
};

/// A buffer object, bound as shader storage or uniform buffer.
class StorageBuffer
{
public:
  StorageBuffer() = default;
  ~StorageBuffer();
  StorageBuffer(const StorageBuffer&) = delete;
  StorageBuffer& operator=(const StorageBuffer&) = delete;

  bool Allocate(std::size_t bytes);
  bool IsAllocated() const { return this->Handle != 0; }
  void Bind(unsigned int index) const;
  void BindUniform(unsigned int index) const;
  void Upload(const void* data, std::size_t bytes) const;
  unsigned int GetHandle() const { return this->Handle; }
  void Read(std::size_t offset, std::size_t bytes, void* data) const;
  std::size_t Bytes() const { return this->ByteSize; }
  void Release();

private:
  unsigned int Handle = 0;
  std::size_t ByteSize = 0;
};

/**
 * Depth-only layered shadow maps: a 2D array texture with depth comparison (for
 * sampler2DArrayShadow) and a framebuffer to render one layer at a time.
 */
class ShadowMapArray
{
public:
  ShadowMapArray() = default;
  ~ShadowMapArray();
  ShadowMapArray(const ShadowMapArray&) = delete;
  ShadowMapArray& operator=(const ShadowMapArray&) = delete;

  bool Allocate(int size, int layers);
  /// Framebuffer name with `layer` attached as depth, to bind through vtkOpenGLState.
  unsigned int PrepareLayer(int layer);
  /// The depth texture's name (a depth attachment for the layers' translucent casters).
  unsigned int GetTexture() const { return this->Texture; }
  int Size() const { return this->Resolution; }
  int Layers() const { return this->LayerCount; }
  bool IsAllocated() const { return this->Texture != 0 || this->Framebuffer != 0; }
  std::size_t Bytes() const;
  void Release();

private:
  unsigned int Texture = 0;
  unsigned int Framebuffer = 0;
  int Resolution = 0;
  int LayerCount = 0;
};

/// A framebuffer without attachments: rasterization only, for image/buffer side effects.
class EmptyFramebuffer
{
public:
  EmptyFramebuffer() = default;
  ~EmptyFramebuffer();
  EmptyFramebuffer(const EmptyFramebuffer&) = delete;
  EmptyFramebuffer& operator=(const EmptyFramebuffer&) = delete;

  /// Create (or resize) and return the framebuffer name, to bind through vtkOpenGLState.
  unsigned int Prepare(int width, int height);
  bool IsAllocated() const { return this->Handle != 0; }
  void Release();

private:
  unsigned int Handle = 0;
  int Width = 0;
  int Height = 0;
};

/// GPU time of one stage: a pair of GL_TIMESTAMP queries around it (timestamps, unlike
/// GL_TIME_ELAPSED, also work when stages nest).
class StageTimer
{
public:
  StageTimer() = default;
  ~StageTimer();
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

  void Begin();
  void End();
  /// Milliseconds of the last Begin/End pair (waits for the GPU); 0 if none.
  double Milliseconds();
  bool IsAllocated() const { return this->Queries[0] != 0; }
  void Release();

private:
  unsigned int Queries[2] = { 0, 0 };
  bool Pending = false;
};

/// Bind level 0 of a 2D texture to image unit `unit` as `format` (e.g. GL_RGBA16F).
void BindImage2D(unsigned int unit, vtkTextureObject* texture, unsigned int access,
  unsigned int format);

/// What is attached to `attachment` of framebuffer `framebuffer`: its name, internal
/// format, samples (0 without multisampling), width and height in `description`; returns
/// GL_RENDERBUFFER, GL_TEXTURE (level 0 of a 2D or 2D multisample texture) or GL_NONE
/// (nothing, or an attachment described otherwise: a layer, a cube face, a mip level).
unsigned int DescribeAttachment(int framebuffer, unsigned int attachment, int description[5]);

/// The bound draw framebuffer, its draw buffer (GL_DRAW_BUFFER0) and what DescribeAttachment
/// says of that colour attachment and of the depth attachment (`types`: what it returned for
/// each); false for a default framebuffer, whose buffers cannot be described.
bool DescribeDrawTarget(
  int& framebuffer, int& buffer, int color[5], int depth[5], unsigned int types[2]);

/// Texture units for a dispatch's 2D inputs: activates each texture, deactivates them after.
class ScopedTextures
{
public:
  explicit ScopedTextures(std::initializer_list<vtkTextureObject*> textures);
  ~ScopedTextures();
  /// False when a texture got no unit (see SamplerBindings::Complete).
  bool Complete() const { return !this->Failed; }
  ScopedTextures(const ScopedTextures&) = delete;
  ScopedTextures& operator=(const ScopedTextures&) = delete;

private:
  vtkTextureObject* Textures[8];
  int Count = 0;
  bool Failed = false;
};

/// A full-screen pass of `fragment`: built on first use, made current afterwards. Null when
/// it did not compile.
vtkShaderProgram* ReadyQuad(
  std::unique_ptr<vtkOpenGLQuadHelper>& quad, vtkOpenGLRenderWindow* renWin, const char* fragment);

/// A 2D texture of `internalFormat` (float data, 4, 2 or 1 components), nearest filtered, for
/// image results.
vtkSmartPointer<vtkTextureObject> NewImageTexture(vtkOpenGLRenderWindow* renWin,
  int internalFormat, int width, int height, int components = 4);

/// Empty when the current context can make (and attach) `width` x `height` 2D images, else
/// a message naming the size and the GL limit it exceeds (GL_MAX_TEXTURE_SIZE, or a smaller
/// GL_MAX_FRAMEBUFFER_WIDTH / HEIGHT). `what` names the image ("the viewport").
std::string ImageSizeError(const char* what, int width, int height);

/// The size of level 0 of a 2D texture as GL holds it. vtkTextureObject remembers the size it
/// was last asked for, even when GL refused it (a resize beyond the limits fails and keeps
/// the old storage): read-backs must be sized from this one.
void StoredSize(vtkTextureObject* texture, int& width, int& height);

/// Make `window`'s context current for a read-back; false when it cannot be (the context is
/// current in another thread: another context would answer).
bool MakeCurrentForReading(vtkOpenGLRenderWindow* window);

/// The current context's OpenGL version.
void ContextVersion(int& major, int& minor);

/// The current context's GL_RENDERER string.
std::string RendererName();

/// Whether the current context lists `name` among its extensions.
bool HasExtension(const char* name);

/// Memory the current context can still allocate, in bytes, or -1 where nothing says.
/// `source` names where the number came from: the driver's free video memory
/// (GL_NVX_gpu_memory_info, GL_ATI_meminfo), else the host's available memory and the
/// process's address-space limit (software rasterizers and integrated GPUs allocate there).
long long AvailableMemory(std::string& source);

/// Drain the GL error queue; returns the number of errors that were pending.
int ClearErrors();

/// A GLSL compiler log with the file numbers of the embedded shaders' `#line` directives
/// replaced by the files' names.
std::string NameShaderFiles(const std::string& log);

}

#endif
