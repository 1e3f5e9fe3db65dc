/* One declaration of each uniform block for both languages (the *_block.h headers): the
   macros and types below read as GLSL in the shaders and as C++ in the stages that fill the
   blocks. In C++, vec4, ivec4 and mat4 are 16-byte aligned and a block is a 16-byte aligned
   struct in namespace voxelgi::glsl, so that a block made of scalars, 4-vectors, 4x4 matrices,
   structs of those and arrays of 4-vectors, matrices and structs has std140 offsets in C++
   too. Other GLSL types have no C++ meaning here on purpose: an array of scalars (a 16-byte
   stride in std140) or a vec3 would have another layout in C++; declare vec4s instead. */
#ifndef VOXELGI_SHADER_INTEROP
#define VOXELGI_SHADER_INTEROP

#ifdef __cplusplus
namespace voxelgi
{
namespace glsl
{
struct alignas(16) vec4
{
  float v[4];
  float& operator[](int i) { return this->v[i]; }
  float operator[](int i) const { return this->v[i]; }
};
struct alignas(16) ivec4
{
  int v[4];
  int& operator[](int i) { return this->v[i]; }
  int operator[](int i) const { return this->v[i]; }
};
/* Column-major, as in GLSL: m[column][row]. */
struct alignas(16) mat4
{
  vec4 columns[4];
  vec4& operator[](int c) { return this->columns[c]; }
  const vec4& operator[](int c) const { return this->columns[c]; }
};
}
}
#define VOXELGI_INTEROP_BEGIN \
  namespace voxelgi           \
  {                           \
  namespace glsl              \
  {
#define VOXELGI_INTEROP_END \
  }                         \
  }
#define VOXELGI_UNIFORM_BLOCK(name, point) struct alignas(16) name
#else
#define VOXELGI_INTEROP_BEGIN
#define VOXELGI_INTEROP_END
#define VOXELGI_UNIFORM_BLOCK(name, point) layout(std140, binding = point) uniform name
#endif

#endif
