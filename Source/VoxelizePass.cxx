#include "Voxelizer.h"

#include "VoxelGIShaders.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <regex>
#include <sstream>

namespace voxelgi
{

namespace
{
constexpr int LocalSize = 4;
constexpr unsigned int FlagUnit = 0;

int Channels(bool emission)
{
  return Voxelizer::BaseChannels + (emission ? Voxelizer::EmissionChannels : 0);
}

std::size_t Cube(int resolution)
{
  const std::size_t n = static_cast<std::size_t>(resolution);
  return n * n * n;
}
}

std::size_t Voxelizer::RequiredBytes(int resolution, bool emission)
{
  // accumulators (4 B per channel) + flag (1 B) + albedo, normal (4 B) [+ emission (8 B)]
  const std::size_t perVoxel = 4 * Channels(emission) + 1 + 4 + 4 + (emission ? 8 : 0);
  return Cube(resolution) * perVoxel;
}

std::string Voxelizer::Defines() const
{
  return "#define VOXEL_CHANNELS " + std::to_string(Channels(this->Emission)) + "\n";
}

bool Voxelizer::Prepare(int resolution, bool emission, std::string& error)
{
  const std::size_t channelBytes = Cube(resolution) * 4;
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  if (maxBlock > 0 && channelBytes > static_cast<std::size_t>(maxBlock))
  {
    std::ostringstream msg;
    msg << "voxel resolution " << resolution << " needs " << channelBytes / (1024 * 1024)
        << " MiB per accumulator channel, above this GL's shader storage block limit of "
        << maxBlock / (1024 * 1024) << " MiB";
    error = msg.str();
    return false;
  }
  const bool variantChanged = emission != this->Emission || !this->ClearProgram.IsReady();
  this->Resolution = resolution;
  this->Emission = emission;
  bool ok = true;
  for (int c = 0; c < Channels(emission); ++c)
  {
    ok = ok && this->Accumulators[c].Allocate(channelBytes);
  }
  for (int c = Channels(emission); c < BaseChannels + EmissionChannels; ++c)
  {
    this->Accumulators[c].Release();
  }
  ok = ok && this->FlagVolume.Allocate(GL_R8UI, resolution);
  ok = ok && this->AlbedoVolume.Allocate(GL_RGBA8, resolution);
  ok = ok && this->NormalVolume.Allocate(GL_RGBA8, resolution);
  if (emission)
  {
    ok = ok && this->EmissionVolume.Allocate(GL_RGBA16F, resolution);
  }
  else
  {
    this->EmissionVolume.Release();
  }
  if (!ok)
  {
    std::ostringstream msg;
    msg << "could not allocate the voxel volumes for resolution " << resolution << " ("
        << RequiredBytes(resolution, emission) / (1024 * 1024) << " MiB of GPU memory)";
    error = msg.str();
    this->ReleaseGraphicsResources();
    return false;
  }
  if (variantChanged)
  {
    std::string log;
    if (!this->ClearProgram.Build(this->Defines(), shaders::clear_dynamic_comp, log) ||
      !this->ResolveProgram.Build(this->Defines(), shaders::voxel_resolve_comp, log))
    {
      error = "voxel compute shaders failed to build: " + log;
      this->ReleaseGraphicsResources();
      return false;
    }
  }
  return true;
}

void Voxelizer::BindForRendering() const
{
  for (int c = 0; c < Channels(this->Emission); ++c)
  {
    this->Accumulators[c].Bind(static_cast<unsigned int>(c));
  }
  this->FlagVolume.BindImage(FlagUnit, GL_READ_WRITE);
}

void Voxelizer::Barrier()
{
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
    GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void Voxelizer::Clear(vtkOpenGLRenderWindow* renWin, bool all)
{
  this->BindForRendering();
  this->ClearProgram.Use(renWin);
  this->ClearProgram.SetInt("voxelResolution", this->Resolution);
  this->ClearProgram.SetInt("clearStatic", all ? 1 : 0);
  this->ClearProgram.DispatchCube(this->Resolution, LocalSize);
  Barrier();
}

void Voxelizer::Resolve(vtkOpenGLRenderWindow* renWin, float emissionScale)
{
  for (int c = 0; c < Channels(this->Emission); ++c)
  {
    this->Accumulators[c].Bind(static_cast<unsigned int>(c));
  }
  this->AlbedoVolume.BindImage(1, GL_WRITE_ONLY);
  this->NormalVolume.BindImage(2, GL_WRITE_ONLY);
  if (this->Emission)
  {
    this->EmissionVolume.BindImage(3, GL_WRITE_ONLY);
  }
  this->ResolveProgram.Use(renWin);
  this->ResolveProgram.SetInt("voxelResolution", this->Resolution);
  if (this->Emission)
  {
    this->ResolveProgram.SetFloat("emissionScale", emissionScale);
  }
  this->ResolveProgram.DispatchCube(this->Resolution, LocalSize);
  Barrier();
}

void Voxelizer::PreReplaceShaders(std::string& geometry, std::string& fragment)
{
  geometry = shaders::voxelize_geom;
  // The voxels store the colour VTK would shade with, before lighting; textures still apply.
  vtkShaderProgram::Substitute(
    fragment, "//VTK::Light::Impl", "gl_FragData[0] = vec4(diffuseColor, opacity);\n");
}

void Voxelizer::PostReplaceShaders(std::string& geometry, std::string& fragment) const
{
  // VTK passes varyings through a geometry shader as `nameGSOutput = nameVSOutput[i];`.
  // Blend the three inputs with the emitted vertex's barycentric weights instead, so the
  // attributes stay exact on the dilated triangle or bounding rectangle.
  static const std::regex perVertex(R"((\w+)\[i\]((?:\.\w+|\[\w+\])*))");
  geometry = std::regex_replace(geometry, perVertex,
    "(voxelBary.x * $1[0]$2 + voxelBary.y * $1[1]$2 + voxelBary.z * $1[2]$2)");

  vtkShaderProgram::Substitute(fragment, "//VTK::System::Dec",
    std::string("//VTK::System::Dec\n") + shaders::voxelize_extensions_glsl + this->Defines());
  const std::size_t mainPos = fragment.find("void main()");
  if (mainPos != std::string::npos)
  {
    fragment.insert(mainPos, std::string(shaders::voxelize_frag) + "\n");
  }
  const std::size_t end = fragment.rfind('}');
  if (end != std::string::npos)
  {
    fragment.insert(end, "  voxelWrite(gl_FragData[0]);\n");
  }
}

void Voxelizer::SetShaderParameters(
  vtkShaderProgram* program, bool staticPass, const double emission[3]) const
{
  program->SetUniformi("voxelResolution", this->Resolution);
  program->SetUniformi("voxelStaticPass", staticPass ? 1 : 0);
  program->SetUniformi("voxelDilate", this->HardwareConservative ? 0 : 1);
  program->SetUniformi("voxelFlag", static_cast<int>(FlagUnit));
  const float e[3] = { static_cast<float>(emission[0]), static_cast<float>(emission[1]),
    static_cast<float>(emission[2]) };
  program->SetUniform3f("voxelEmission", e);
}

std::size_t Voxelizer::MemoryBytes() const
{
  std::size_t bytes = this->FlagVolume.Bytes() + this->AlbedoVolume.Bytes() +
    this->NormalVolume.Bytes() + this->EmissionVolume.Bytes();
  for (const auto& buffer : this->Accumulators)
  {
    bytes += buffer.Bytes();
  }
  return bytes;
}

std::size_t Voxelizer::EmissionBytes() const
{
  std::size_t bytes = this->EmissionVolume.Bytes();
  for (int c = BaseChannels; c < BaseChannels + EmissionChannels; ++c)
  {
    bytes += this->Accumulators[c].Bytes();
  }
  return bytes;
}

void Voxelizer::ReadCounts(std::vector<unsigned int>& counts) const
{
  counts.resize(Cube(this->Resolution));
  Barrier();
  this->Accumulators[0].Read(0, counts.size() * sizeof(unsigned int), counts.data());
}

void Voxelizer::ReadFlags(std::vector<unsigned char>& flags) const
{
  flags.resize(Cube(this->Resolution));
  Barrier();
  this->FlagVolume.Read(GL_RED_INTEGER, GL_UNSIGNED_BYTE, flags.data());
}

void Voxelizer::ReleaseGraphicsResources()
{
  for (auto& buffer : this->Accumulators)
  {
    buffer.Release();
  }
  this->FlagVolume.Release();
  this->AlbedoVolume.Release();
  this->NormalVolume.Release();
  this->EmissionVolume.Release();
  this->ClearProgram.Release();
  this->ResolveProgram.Release();
  this->Resolution = 0;
}

}
