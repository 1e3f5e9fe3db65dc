#include "VoxelizePass.h"

#include "Frame.h"
#include "PropReader.h"
#include "Ranks.h"
#include "VoxelGIShaders.h"
#include "StageIds.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataObject.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPolyDataMapper.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <regex>
#include <sstream>

namespace voxelgi
{

vtkStandardNewMacro(VoxelizePass);

namespace
{
constexpr int ClearnessChannel = VOXELGI_BASE_CHANNELS + VOXELGI_EMISSION_CHANNELS;

/// Whether the variant sums channel c (voxel_common.glsl's order, then clearness).
bool Used(int c, bool emission, bool translucent)
{
  return c < VOXELGI_BASE_CHANNELS || (c < ClearnessChannel ? emission : translucent);
}

int Channels(bool emission, bool translucent)
{
  return VOXELGI_BASE_CHANNELS + (emission ? VOXELGI_EMISSION_CHANNELS : 0) + (translucent ? 1 : 0);
}

unsigned int Binding(int c)
{
  return static_cast<unsigned int>(c < ClearnessChannel ? c : VOXELGI_CLEARNESS_BINDING);
}

std::size_t Cube(int resolution)
{
  const std::size_t n = static_cast<std::size_t>(resolution);
  return n * n * n;
}

/// The brick list: indirect dispatch arguments and padding (4 uints), then one uint a brick.
std::size_t BrickListBytes(int resolution)
{
  return 4 * (4 + Cube(resolution / VOXELGI_LOCAL_SIZE));
}

void Barrier()
{
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
    GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
    GL_COMMAND_BARRIER_BIT);
}
}

//------------------------------------------------------------------------------
VoxelizePass::VoxelizePass() = default;
VoxelizePass::~VoxelizePass() = default;

std::size_t VoxelizePass::RequiredBytes(int resolution, bool emission, bool translucent)
{
  // accumulators (4 B per channel) + flag (1 B) + albedo, normal (4 B) [+ emission (8 B)]
  const std::size_t perVoxel =
    4 * Channels(emission, translucent) + 1 + 4 + 4 + (emission ? 8 : 0);
  return Cube(resolution) * perVoxel + BrickListBytes(resolution);
}

std::string VoxelizePass::Defines() const
{
  return std::string(this->Emission ? "#define VOXELGI_EMISSION\n" : "") +
    (this->Translucent ? "#define VOXELGI_TRANSLUCENT\n" : "");
}

//------------------------------------------------------------------------------
bool VoxelizePass::Prepare(const Frame& frame, std::string& error)
{
  const int resolution = frame.Plan.Voxels.Grid.Resolution;
  const bool emission = frame.Plan.Voxels.Emission;
  const bool translucent = frame.Plan.Voxels.Translucent;
  this->HardwareConservative = frame.Config.HardwareConservativeRaster;
  if (!this->Volumes.Prepare(frame, error))
  {
    this->ReleaseGraphicsResources(frame.Window);
    return false;
  }
  if (resolution == this->Resolution && emission == this->Emission &&
    translucent == this->Translucent && this->ClearProgram.IsReady())
  {
    return this->PrepareResolve(error);
  }
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
  const bool variantChanged =
    emission != this->Emission || translucent != this->Translucent || !this->ClearProgram.IsReady();
  this->Resolution = resolution;
  this->Emission = emission;
  this->Translucent = translucent;
  if (!this->Allocate(channelBytes))
  {
    std::ostringstream msg;
    msg << "could not allocate the voxel volumes for resolution " << resolution << " ("
        << RequiredBytes(resolution, emission, translucent) / (1024 * 1024)
        << " MiB of GPU memory)";
    error = msg.str();
    this->ReleaseGraphicsResources(frame.Window);
    return false;
  }
  this->ListEveryBrick(); // new buffers hold anything: the first clear covers every brick
  if (variantChanged)
  {
    std::string log;
    if (!this->ClearProgram.Build(this->Defines(), shaders::clear_dynamic_comp, log))
    {
      error = "voxel compute shaders failed to build: " + log;
      this->ReleaseGraphicsResources(frame.Window);
      return false;
    }
    this->ShaderStageTime.Modified(); // the mapper shaders depend on the variant
  }
  if (!this->Compute.Prepare(this->Defines(), error) || !this->PrepareResolve(error))
  {
    this->ReleaseGraphicsResources(frame.Window);
    return false;
  }
  return true;
}

bool VoxelizePass::Allocate(std::size_t channelBytes)
{
  const int resolution = this->Resolution;
  bool ok = true;
  for (int c = 0; c < static_cast<int>(this->Accumulators.size()); ++c)
  {
    if (Used(c, this->Emission, this->Translucent))
    {
      ok = ok && this->Accumulators[c].Allocate(channelBytes);
    }
    else
    {
      this->Accumulators[c].Release();
    }
  }
  ok = ok && this->BrickList.Allocate(BrickListBytes(resolution));
  ok = ok && this->FlagVolume.Allocate(GL_R8UI, resolution);
  ok = ok && this->AlbedoVolume.Allocate(GL_RGBA8, resolution);
  ok = ok && this->NormalVolume.Allocate(GL_RGBA8, resolution);
  if (this->Emission)
  {
    ok = ok && this->EmissionVolume.Allocate(GL_RGBA16F, resolution);
  }
  else
  {
    this->EmissionVolume.Release();
  }
  return ok;
}

bool VoxelizePass::PrepareResolve(std::string& error)
{
  // The variant with volumes reads their voxels; without, nothing is bound for them.
  const std::string volumes = this->Volumes.GetGrid() ? "#define VOXELGI_VOLUMES\n" : "";
  return this->ResolveProgram.BuildOnce(
    shaders::voxel_resolve_comp, "voxel resolve", error, this->Defines() + volumes);
}

void VoxelizePass::ListEveryBrick()
{
  const unsigned int bricks = static_cast<unsigned int>(this->Resolution / VOXELGI_LOCAL_SIZE);
  std::vector<unsigned int> list{ bricks * bricks * bricks, 1, 1, 0 };
  for (unsigned int z = 0; z < bricks; ++z)
  {
    for (unsigned int y = 0; y < bricks; ++y)
    {
      for (unsigned int x = 0; x < bricks; ++x)
      {
        list.push_back(x | (y << 10) | (z << 20)); // as voxelBrickPack
      }
    }
  }
  this->BrickList.Upload(list.data(), list.size() * sizeof(unsigned int));
}

//------------------------------------------------------------------------------
void VoxelizePass::Run(const Frame& frame)
{
  const bool full = frame.Plan.Voxels.Full;
  this->Clear(frame);

  // Actors whose triangles the compute path reads go there; the others draw through copies
  // of their mappers.
  std::vector<vtkProp*> staticProps;
  std::vector<vtkProp*> dynamicProps;
  std::vector<VoxelizeCompute::Item> staticItems;
  std::vector<VoxelizeCompute::Item> dynamicItems;
  this->PropEmissions.clear();
  for (const ActorRecord& record : *frame.Actors)
  {
    if (!full && !record.Dynamic)
    {
      continue; // its voxels are kept
    }
    const SceneBuffers::Entry* buffers = this->Resident(frame, record.Actor);
    if (buffers)
    {
      (record.Dynamic ? dynamicItems : staticItems).push_back({ record.Actor, buffers, record.Emission });
      continue;
    }
    (record.Dynamic ? dynamicProps : staticProps).push_back(record.Actor);
    this->PropEmissions[record.Actor] = record.Emission;
  }
  this->AimCamera(frame);

  vtkOpenGLState* ostate = frame.Window->GetState();
  ostate->PushFramebufferBindings();
  ostate->vtkglBindFramebuffer(
    GL_FRAMEBUFFER, this->Framebuffer.Prepare(this->Resolution, this->Resolution));
  {
    vtkOpenGLState::ScopedglViewport viewport(ostate);
    vtkOpenGLState::ScopedglEnableDisable scissor(ostate, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglEnableDisable depth(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable cull(ostate, GL_CULL_FACE);
    ostate->vtkglViewport(0, 0, this->Resolution, this->Resolution);
    ostate->vtkglDisable(GL_SCISSOR_TEST);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    ostate->vtkglDisable(GL_BLEND);
    // Depth is computed in the shader; clamping keeps the rasterizer from clipping it.
    glEnable(GL_DEPTH_CLAMP);
    if (this->HardwareConservative)
    {
      glEnable(GL_CONSERVATIVE_RASTERIZATION_NV);
    }
    if (full)
    {
      this->Draw(frame, staticProps, staticItems, true);
      this->MergeFlags(frame);
    }
    if (!dynamicProps.empty() || !dynamicItems.empty())
    {
      this->Draw(frame, dynamicProps, dynamicItems, false);
    }
    glDisable(GL_DEPTH_CLAMP);
    if (this->HardwareConservative)
    {
      glDisable(GL_CONSERVATIVE_RASTERIZATION_NV);
    }
  }
  ostate->PopFramebufferBindings();
  if (full)
  {
    this->Copies.Retain(*frame.Actors, frame.Window); // actors come and go in full rebuilds
    this->Compute.Retain(*frame.Actors);
  }

  // Line and point primitives of mixed polydata cannot feed the triangle geometry shader;
  // GL rejects those draws (they have no area to voxelize). Do not leave the errors to VTK.
  ClearErrors();
  this->MergeSums(frame);
  this->Volumes.Run(frame);
  this->Resolve(frame);
}

const SceneBuffers::Entry* VoxelizePass::Resident(const Frame& frame, vtkActor* actor)
{
  return frame.Config.ComputeVoxelization ? this->Compute.Read(actor) : nullptr;
}

void VoxelizePass::MergeFlags(const Frame& frame)
{
  Ranks& ranks = *frame.Processes;
  if (!ranks.Distributed())
  {
    return;
  }
  std::vector<unsigned char> flags(Cube(this->Resolution));
  this->FlagVolume.Read(GL_RED_INTEGER, GL_UNSIGNED_BYTE, flags.data());
  ranks.MaxVolume(flags.data(), this->Resolution, VOXELGI_LOCAL_SIZE);
  this->FlagVolume.Upload(GL_RED_INTEGER, GL_UNSIGNED_BYTE, flags.data());
  Barrier();
}

void VoxelizePass::MergeSums(const Frame& frame)
{
  Ranks& ranks = *frame.Processes;
  if (!ranks.Distributed())
  {
    return;
  }
  const std::size_t voxels = Cube(this->Resolution);
  std::vector<unsigned char> flags;
  if (!frame.Plan.Voxels.Full && ranks.Rank() != 0)
  {
    flags.resize(voxels);
    this->FlagVolume.Read(GL_RED_INTEGER, GL_UNSIGNED_BYTE, flags.data());
  }
  std::vector<unsigned int> sums(voxels);
  for (int c = 0; c < static_cast<int>(this->Accumulators.size()); ++c)
  {
    if (!this->Accumulators[c].IsAllocated())
    {
      continue;
    }
    this->Accumulators[c].Read(0, voxels * sizeof(unsigned int), sums.data());
    for (std::size_t i = 0; i < flags.size(); ++i)
    {
      sums[i] = flags[i] ? 0u : sums[i];
    }
    ranks.SumVolume(sums.data(), this->Resolution, VOXELGI_LOCAL_SIZE);
    this->Accumulators[c].Upload(sums.data(), voxels * sizeof(unsigned int));
  }
  Barrier();
}

void VoxelizePass::AimCamera(const Frame& frame)
{
  // An orthographic camera whose view volume is the grid cube: VTK's mappers then compose
  // model, shift-scale and grid matrices in double precision for us.
  const glm::dvec3 center = frame.Grid.Center();
  const double half = 0.5 * frame.Grid.Size();
  vtkCamera* camera = this->View.GetCamera();
  camera->SetFocalPoint(center.x, center.y, center.z);
  camera->SetPosition(center.x, center.y, center.z + half);
  camera->SetViewUp(0.0, 1.0, 0.0);
  vtkNew<vtkMatrix4x4> projection;
  projection->SetElement(0, 0, 1.0 / half);
  projection->SetElement(1, 1, 1.0 / half);
  projection->SetElement(2, 2, 1.0 / half);
  projection->SetElement(2, 3, 1.0);
  camera->SetExplicitProjectionTransformMatrix(projection);
  camera->SetUseExplicitProjectionTransformMatrix(true);
}

void VoxelizePass::Draw(const Frame& frame, std::vector<vtkProp*>& props,
  const std::vector<VoxelizeCompute::Item>& items, bool staticPass)
{
  ScopedStage stage(*frame.Clock,
    staticPass ? stage::VoxelizeStatic : stage::VoxelizeDynamic);
  if (!props.empty())
  {
    this->StaticPass = staticPass;
    // The user's renderer and its camera are left alone (observers of its ActiveCameraEvent
    // may render other windows or delete props): the props draw through a renderer of ours.
    vtkRenderState state(this->View.Attach(frame.Window));
    state.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
    this->Render(&state);
  }
  this->BindAccumulators();
  this->Compute.Draw(frame, items, staticPass);
  Barrier();
}

namespace
{
/// Whether `actor` draws points or lines alone (ParaView's outline, streamlines drawn as
/// lines): a polydata mapper (a glyph mapper's input is its instances' points) whose input
/// has cells, none of them polygons or strips (an input its pipeline has not yet filled is
/// drawn). They have no area to voxelize, and voxelize.geom takes triangles: drawn, they
/// raise GL_INVALID_OPERATION.
bool DrawsPointsAndLinesOnly(vtkActor* actor)
{
  auto* mapper = vtkPolyDataMapper::SafeDownCast(actor ? actor->GetMapper() : nullptr);
  vtkDataObject* input = mapper ? mapper->GetInputDataObject(0, 0) : nullptr;
  return input && input->GetNumberOfElements(vtkDataObject::CELL) > 0 &&
    PointsAndLinesOnly(input);
}
}

void VoxelizePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->PreRender(s);
  this->BindAccumulators();
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkActor* actor = vtkActor::SafeDownCast(s->GetPropArray()[i]);
    if (!DrawsPointsAndLinesOnly(actor))
    {
      this->NumberOfRenderedProps += this->Copies.Draw(actor, s->GetRenderer());
    }
  }
  this->PostRender(s);
}

//------------------------------------------------------------------------------
void VoxelizePass::BindAccumulators() const
{
  for (int c = 0; c < static_cast<int>(this->Accumulators.size()); ++c)
  {
    if (this->Accumulators[c].IsAllocated())
    {
      this->Accumulators[c].Bind(Binding(c));
    }
  }
  this->FlagVolume.BindImage(VOXELGI_FLAG_IMAGE_UNIT, GL_READ_WRITE);
}

void VoxelizePass::Clear(const Frame& frame)
{
  ScopedStage stage(*frame.Clock, stage::Clear);
  this->BindAccumulators();
  this->BrickList.Bind(VOXELGI_BRICK_LIST_BINDING);
  this->ClearProgram.Use(frame.Window);
  this->ClearProgram.SetInt("clearStatic", frame.Plan.Voxels.Full ? 1 : 0);
  this->ClearProgram.DispatchIndirect(this->BrickList);
  Barrier();
}

void VoxelizePass::Resolve(const Frame& frame)
{
  ScopedStage stage(*frame.Clock, stage::Resolve);
  const unsigned int emptyList[4] = { 0, 1, 1, 0 }; // no brick yet; 1 x 1 in y and z
  this->BrickList.Upload(emptyList, sizeof(emptyList));
  this->BrickList.Bind(VOXELGI_BRICK_LIST_BINDING);
  this->BindAccumulators();
  this->AlbedoVolume.BindImage(1, GL_WRITE_ONLY);
  this->NormalVolume.BindImage(2, GL_WRITE_ONLY);
  if (this->Emission)
  {
    this->EmissionVolume.BindImage(3, GL_WRITE_ONLY);
  }
  if (const Volume3D* volumes = this->Volumes.GetGrid())
  {
    volumes->BindImage(4, GL_READ_ONLY);
  }
  this->ResolveProgram.Use(frame.Window);
  this->ResolveProgram.DispatchCube(this->Resolution, VOXELGI_LOCAL_SIZE);
  Barrier();
}

//------------------------------------------------------------------------------
bool VoxelizePass::PreReplaceShaderValues(
  std::string&, std::string& geometry, std::string& fragment, vtkAbstractMapper*, vtkProp*)
{
  geometry = shaders::voxelize_geom;
  // The voxels store the colour VTK would shade with, before lighting; textures still apply.
  vtkShaderProgram::Substitute(
    fragment, "//VTK::Light::Impl", "gl_FragData[0] = vec4(diffuseColor, opacity);\n");
  return true;
}

bool VoxelizePass::PostReplaceShaderValues(
  std::string&, std::string& geometry, std::string& fragment, vtkAbstractMapper*, vtkProp*)
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
  return true;
}

bool VoxelizePass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  float e[3] = { 0.f, 0.f, 0.f };
  auto found = this->PropEmissions.find(this->Copies.Original(prop));
  if (found != this->PropEmissions.end())
  {
    for (int c = 0; c < 3; ++c)
    {
      e[c] = static_cast<float>(found->second[c]);
    }
  }
  program->SetUniformi("voxelStaticPass", this->StaticPass ? 1 : 0);
  program->SetUniformi("voxelDilate", this->HardwareConservative ? 0 : 1);
  program->SetUniform3f("voxelEmission", e);
  return true;
}

//------------------------------------------------------------------------------
std::size_t VoxelizePass::MemoryBytes() const
{
  std::size_t bytes = this->BrickList.Bytes() + this->FlagVolume.Bytes() + this->AlbedoVolume.Bytes() +
    this->NormalVolume.Bytes() + this->EmissionVolume.Bytes();
  for (const auto& buffer : this->Accumulators)
  {
    bytes += buffer.Bytes();
  }
  return bytes;
}

std::size_t VoxelizePass::EmissionBytes() const
{
  std::size_t bytes = this->EmissionVolume.Bytes();
  for (int c = VOXELGI_BASE_CHANNELS; c < ClearnessChannel; ++c)
  {
    bytes += this->Accumulators[c].Bytes();
  }
  return bytes;
}

void VoxelizePass::ReadCounts(std::vector<unsigned int>& counts) const
{
  counts.resize(Cube(this->Resolution));
  Barrier();
  this->Accumulators[0].Read(0, counts.size() * sizeof(unsigned int), counts.data());
}

void VoxelizePass::ReadFlags(std::vector<unsigned char>& flags) const
{
  flags.resize(Cube(this->Resolution));
  Barrier();
  this->FlagVolume.Read(GL_RED_INTEGER, GL_UNSIGNED_BYTE, flags.data());
}

void VoxelizePass::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto& buffer : this->Accumulators)
  {
    buffer.Release();
  }
  this->BrickList.Release();
  this->FlagVolume.Release();
  this->AlbedoVolume.Release();
  this->NormalVolume.Release();
  this->EmissionVolume.Release();
  this->ClearProgram.Release();
  this->ResolveProgram.Release();
  this->Volumes.ReleaseGraphicsResources(window);
  this->Framebuffer.Release();
  this->Copies.ReleaseGraphicsResources(window);
  this->Compute.ReleaseGraphicsResources();
  this->View.Release();
  this->Resolution = 0;
}

}
