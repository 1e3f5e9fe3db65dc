#include "ShadowMaps.h"

#include "Frame.h"
#include "LightBlock.h"
#include "VoxelGrid.h"
#include "StageIds.h"
#include "VoxelizePass.h"

#include "vtkActor.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

namespace voxelgi
{

namespace
{
// A point light's cube faces see a little beyond 90 degrees, so that a filter's taps near a
// face's edge stay on that face.
constexpr double CubeFaceTan = 1.05;

// Layers of a light's map: none for a headlight, six cube faces for a point light (a
// positional light whose cone is 90 degrees or wider), else one.
int LayerCount(vtkLight* light)
{
  if (!light || light->LightTypeIsHeadlight())
  {
    return 0;
  }
  return light->GetPositional() && light->GetConeAngle() >= 90.0 ? 6 : 1;
}

// 32-bit depth per texel.
std::size_t MapBytes(int size, int layers)
{
  return static_cast<std::size_t>(size) * size * layers * 4;
}

// Aim `camera` from the light over the grid and give it an explicit projection: orthographic
// over the grid's bounding sphere for a directional light, a perspective frustum of the
// spot's cone for a spot light, and of cube face `face` (+x -x +y -y +z -z) for a point
// light. Returns the width of a map texel of `size` in voxels: x + y * distance.
glm::dvec2 AimLightCamera(
  vtkCamera* camera, vtkLight* light, const VoxelGrid& grid, int face, int size)
{
  const glm::dvec3 center = grid.Center();
  const double radius = 0.5 * std::sqrt(3.0) * grid.Size();
  double position[3], focal[3];
  light->GetTransformedPosition(position);
  light->GetTransformedFocalPoint(focal);
  glm::dvec3 dir(focal[0] - position[0], focal[1] - position[1], focal[2] - position[2]);
  dir = glm::length(dir) > 0.0 ? glm::normalize(dir) : glm::dvec3(0, 0, -1);
  const bool cube = LayerCount(light) == 6;
  if (cube)
  {
    dir = glm::dvec3(0.0);
    dir[face / 2] = face % 2 == 0 ? 1.0 : -1.0;
  }
  const glm::dvec3 up = std::abs(dir.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
  vtkNew<vtkMatrix4x4> projection;
  glm::dvec2 texel(0.0);
  if (!light->GetPositional())
  {
    const glm::dvec3 eye = center - dir * (2.0 * radius);
    camera->SetPosition(eye.x, eye.y, eye.z);
    camera->SetFocalPoint(center.x, center.y, center.z);
    // view depth -radius (near) .. -3 radius (far) -> NDC -1 .. 1
    projection->SetElement(0, 0, 1.0 / radius);
    projection->SetElement(1, 1, 1.0 / radius);
    projection->SetElement(2, 2, -1.0 / radius);
    projection->SetElement(2, 3, -2.0);
    texel.x = 2.0 * radius / (size * grid.VoxelSize);
  }
  else
  {
    const glm::dvec3 eye(position[0], position[1], position[2]);
    const glm::dvec3 target = eye + dir;
    camera->SetPosition(eye.x, eye.y, eye.z);
    camera->SetFocalPoint(target.x, target.y, target.z);
    const double farPlane = glm::length(center - eye) + radius;
    const double nearPlane = std::max(farPlane * 1e-3, 1e-6 * radius);
    const double tanHalf = cube
      ? CubeFaceTan
      : std::tan(vtkMath::RadiansFromDegrees(std::min(light->GetConeAngle() + 2.0, 89.0)));
    projection->SetElement(0, 0, 1.0 / tanHalf);
    projection->SetElement(1, 1, 1.0 / tanHalf);
    projection->SetElement(2, 2, (farPlane + nearPlane) / (nearPlane - farPlane));
    projection->SetElement(2, 3, 2.0 * farPlane * nearPlane / (nearPlane - farPlane));
    projection->SetElement(3, 2, -1.0);
    projection->SetElement(3, 3, 0.0);
    texel.y = 2.0 * tanHalf / size;
  }
  camera->SetViewUp(up.x, up.y, up.z);
  camera->SetExplicitProjectionTransformMatrix(projection);
  camera->SetUseExplicitProjectionTransformMatrix(true);
  return texel;
}

// Whether the box `bounds` (world) lies wholly outside one side plane or behind the near
// plane of the view whose clip coordinates `clipFromWorld` gives (the planes are linear in
// clip space, so the corners decide, whatever their w).
bool OutsideView(const double* bounds, vtkMatrix4x4* clipFromWorld)
{
  if (!bounds || !vtkMath::AreBoundsInitialized(bounds))
  {
    return false;
  }
  int outside[5] = { 0, 0, 0, 0, 0 }; // corners beyond x = w, x = -w, y = w, y = -w, z = -w
  for (int corner = 0; corner < 8; ++corner)
  {
    const double world[4] = { bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)],
      bounds[4 + ((corner >> 2) & 1)], 1.0 };
    double clip[4];
    clipFromWorld->MultiplyPoint(world, clip);
    outside[0] += clip[0] > clip[3];
    outside[1] += -clip[0] > clip[3];
    outside[2] += clip[1] > clip[3];
    outside[3] += -clip[1] > clip[3];
    outside[4] += clip[2] < -clip[3];
  }
  return std::any_of(outside, outside + 5, [](int n) { return n == 8; });
}

// Clip coordinates from an actor's shifted model coordinates (SceneBuffers): clip <- world
// <- model <- shifted, row-major doubles in, column-major floats out, composed in double so
// that data far from the origin stays exact.
std::array<float, 16> ClipFromModel(const std::array<double, 16>& clipFromWorld,
  const std::array<double, 16>& worldFromModel, const std::array<double, 3>& shift)
{
  std::array<double, 16> model = worldFromModel;
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      model[4 * r + 3] += worldFromModel[4 * r + c] * shift[c];
    }
  }
  std::array<float, 16> out;
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      double sum = 0.0;
      for (int k = 0; k < 4; ++k)
      {
        sum += clipFromWorld[4 * r + k] * model[4 * k + c];
      }
      out[4 * c + r] = static_cast<float>(sum);
    }
  }
  return out;
}
}

std::size_t ShadowMaps::RequiredBytes(int size, const std::vector<vtkLight*>& lights)
{
  int layers = 0;
  for (std::size_t l = 0; l < lights.size() && l < MaxLights; ++l)
  {
    layers += LayerCount(lights[l]);
  }
  return MapBytes(size, layers);
}

bool ShadowMaps::Prepare(const Frame& frame, std::string& error, std::string& note)
{
  const std::vector<vtkLight*>& used = frame.Lights->GetLights();
  int count = 0;
  bool pixelsMapsOnly = true;
  for (std::size_t l = 0; l < MaxLights; ++l)
  {
    vtkLight* light = l < used.size() ? used[l] : nullptr;
    const int layers = LayerCount(light);
    glsl::ivec4& entry = this->Data.shadowLights[l];
    entry[0] = layers > 0 ? count : -1;
    entry[1] = layers;
    entry[2] = layers > 0 && light->LightTypeIsSceneLight() ? 1 : 0;
    entry[3] = 0;
    pixelsMapsOnly = pixelsMapsOnly && (!light || light->LightTypeIsHeadlight() || entry[2]);
    count += layers;
  }
  this->Data.shadowInfo[0] = pixelsMapsOnly ? 1 : 0;
  if (count == 0)
  {
    this->Maps.Release();
    this->Drawn.clear();
    return true;
  }
  if (!this->Depth.Prepare(error))
  {
    return false;
  }
  if (!this->Allot(frame.Config.ShadowMapResolution, count, note))
  {
    // Not even the smallest maps: every light raymarches the voxels instead.
    for (glsl::ivec4& entry : this->Data.shadowLights)
    {
      entry = { -1, 0, 0, 0 };
    }
    this->Data.shadowInfo[0] = 0;
  }
  if (!(this->Buffer.IsAllocated() || this->Buffer.Allocate(sizeof(Block))))
  {
    error = "could not allocate the shadow maps' uniform buffer";
    return false;
  }
  this->PrepareTransmittance(frame, note);
  return true;
}

void ShadowMaps::PrepareTransmittance(const Frame& frame, std::string& note)
{
  const bool translucent = this->HasMaps() &&
    std::any_of(frame.Actors->begin(), frame.Actors->end(),
      [](const ActorRecord& record) { return record.Translucent; });
  const std::size_t before = this->Transmittance.Bytes();
  std::string error;
  if (!this->Transmittance.Prepare(
        translucent ? this->Maps.Size() : 0, translucent ? this->Maps.Layers() : 0, error))
  {
    note = error + ": translucent actors cast no shadow.";
    this->Transmittance.Prepare(0, 0, error);
  }
  if (this->Transmittance.Bytes() != before)
  {
    this->Drawn.assign(this->Drawn.size(), LayerKey{}); // no layer holds its transmittance
  }
  this->Data.shadowInfo[1] = this->Transmittance.IsAllocated() ? 1 : 0;
}

bool ShadowMaps::Allot(int size, int layers, std::string& note)
{
  const bool decided = this->Wanted[0] == size && this->Wanted[1] == layers;
  if (decided && (this->Maps.IsAllocated() || this->Granted == 0))
  {
    return this->Granted > 0;
  }
  this->Wanted[0] = size;
  this->Wanted[1] = layers;
  this->Drawn.assign(static_cast<std::size_t>(layers), LayerKey{}); // new maps hold nothing
  // The maps degrade instead of turning GI off: halved until they fit the memory the GL
  // reports free (counting what the old maps hold) and GL allocates them.
  std::string source;
  const long long available = AvailableMemory(source);
  const std::size_t budget = available < 0
    ? static_cast<std::size_t>(-1)
    : static_cast<std::size_t>(available) + this->Maps.Bytes();
  this->Granted = size;
  while (this->Granted >= MinSize &&
    (MapBytes(this->Granted, layers) > budget || !this->Maps.Allocate(this->Granted, layers)))
  {
    this->Granted /= 2;
  }
  this->Granted = this->Granted >= MinSize ? this->Granted : 0;
  if (this->Granted != size)
  {
    const auto mib = [](std::size_t bytes) { return bytes / (1024 * 1024); };
    std::ostringstream msg;
    msg << "ShadowMapResolution " << size << " needs " << mib(MapBytes(size, layers))
        << " MiB for " << layers << " shadow maps, but "
        << (available < 0 ? "GL could not allocate them"
                          : std::to_string(mib(budget)) + " MiB are free (" + source + ")")
        << ": ";
    if (this->Granted > 0)
    {
      msg << "they are rendered at " << this->Granted << " texels (" << mib(MapBytes(this->Granted, layers))
          << " MiB).";
    }
    else
    {
      msg << "the lights' shadows are raymarched through the voxels instead.";
      this->Maps.Release();
    }
    note = msg.str();
  }
  return this->Granted > 0;
}

void ShadowMaps::Bind(GLProgram& program, SamplerBindings& samplers) const
{
  program.SetInt("shadowMaps", samplers.Add(this->Maps));
  this->Transmittance.Bind(program, samplers);
  this->Buffer.BindUniform(VOXELGI_SHADOW_BLOCK_BINDING);
}

void ShadowMaps::Run(const Frame& frame)
{
  const LightBlock& lights = *frame.Lights;
  if (!this->HasMaps())
  {
    return;
  }
  std::optional<ScopedStage> stage; // timed from the first layer drawn
  this->ReadCasters(frame);
  // The casters draw through a renderer of ours whose camera is the light's: the user's
  // renderer and camera are left alone (see ViewRenderer).
  vtkRenderer* renderer = this->View.Attach(frame.Window);
  vtkCamera* camera = this->View.GetCamera();
  const VoxelGrid& grid = frame.Grid;
  const int size = this->Maps.Size();
  const std::vector<vtkLight*>& used = lights.GetLights();
  vtkOpenGLState* ostate = frame.Window->GetState();
  ostate->PushFramebufferBindings();
  {
    vtkOpenGLState::ScopedglViewport viewport(ostate);
    vtkOpenGLState::ScopedglEnableDisable scissor(ostate, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglEnableDisable depth(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable cull(ostate, GL_CULL_FACE);
    vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
    vtkOpenGLState::ScopedglDepthFunc depthFunc(ostate);
    vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(ostate);
    vtkOpenGLState::ScopedglClearColor clearColor(ostate);
    ostate->vtkglViewport(0, 0, size, size);
    ostate->vtkglDisable(GL_SCISSOR_TEST);
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_LEQUAL);
    ostate->vtkglDepthMask(GL_TRUE);
    // world <- grid, composed in double with each layer's clip <- world
    vtkNew<vtkMatrix4x4> worldFromGrid;
    for (int a = 0; a < 3; ++a)
    {
      worldFromGrid->SetElement(a, a, grid.VoxelSize);
      worldFromGrid->SetElement(a, 3, grid.Origin[a]);
    }
    for (std::size_t l = 0; l < used.size() && l < MaxLights; ++l)
    {
      const int first = this->Data.shadowLights[l][0];
      for (int face = 0; face < this->Data.shadowLights[l][1]; ++face)
      {
        const glm::dvec2 texel = AimLightCamera(camera, used[l], grid, face, size);
        this->Data.shadowTexels[l][0] = static_cast<float>(texel.x);
        this->Data.shadowTexels[l][1] = static_cast<float>(texel.y);
        vtkNew<vtkMatrix4x4> clipFromWorld;
        clipFromWorld->DeepCopy(camera->GetCompositeProjectionTransformMatrix(1.0, -1, 1));
        this->DrawLayer(frame, first + face, clipFromWorld, renderer, stage);
        vtkNew<vtkMatrix4x4> clipFromGrid;
        vtkMatrix4x4::Multiply4x4(clipFromWorld, worldFromGrid, clipFromGrid);
        glsl::mat4& matrix = this->Data.shadowMatrices[first + face];
        for (int r = 0; r < 4; ++r)
        {
          for (int c = 0; c < 4; ++c)
          {
            matrix[c][r] = static_cast<float>(clipFromGrid->GetElement(r, c));
          }
        }
      }
    }
  }
  ostate->PopFramebufferBindings();
  this->Buffer.Upload(&this->Data, sizeof(Block));
  this->Copies.Retain(*frame.Actors, frame.Window);
}

void ShadowMaps::ReadCasters(const Frame& frame)
{
  this->Casters.clear();
  for (const ActorRecord& record : *frame.Actors)
  {
    if (record.Actor)
    {
      Caster caster{ record.Actor, record.Revision, {}, {},
        this->Voxels.Resident(frame, record.Actor), record.Translucent };
      if (caster.Translucent && (!caster.Buffers || !this->Transmittance.IsAllocated()))
      {
        continue; // only its GPU-resident triangles are drawn into the transmittance
      }
      std::copy_n(&record.Actor->GetMatrix()->Element[0][0], 16, caster.Matrix.begin());
      const double* bounds = record.Actor->GetBounds();
      caster.Bounds = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 }; // uninitialized: never culled
      if (bounds)
      {
        std::copy_n(bounds, 6, caster.Bounds.begin());
      }
      this->Casters.push_back(caster);
    }
  }
}

void ShadowMaps::DrawLayer(const Frame& frame, int layer, vtkMatrix4x4* clipFromWorld,
  vtkRenderer* renderer, std::optional<ScopedStage>& stage)
{
  // The casters a layer sees: each draw through a mapper costs CPU time, and a cube face
  // sees only part of the scene.
  LayerKey key;
  std::copy_n(&clipFromWorld->Element[0][0], 16, key.ClipFromWorld.begin());
  for (const Caster& caster : this->Casters)
  {
    if (!OutsideView(caster.Bounds.data(), clipFromWorld))
    {
      key.Casters.push_back(caster);
    }
  }
  if (this->Drawn.size() <= static_cast<std::size_t>(layer))
  {
    this->Drawn.resize(static_cast<std::size_t>(layer) + 1);
  }
  LayerKey& drawn = this->Drawn[static_cast<std::size_t>(layer)];
  if (key == drawn)
  {
    return; // its depth is still that view of those casters
  }
  if (!stage)
  {
    stage.emplace(*frame.Clock, stage::ShadowMaps);
  }
  this->DrawCasters(frame, layer, key, renderer);
  drawn = std::move(key);
}

void ShadowMaps::DrawCasters(
  const Frame& frame, int layer, const LayerKey& key, vtkRenderer* renderer)
{
  vtkOpenGLState* ostate = frame.Window->GetState();
  ostate->vtkglBindFramebuffer(GL_FRAMEBUFFER, this->Maps.PrepareLayer(layer));
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
  bool resident = false;
  for (const Caster& caster : key.Casters)
  {
    if (!caster.Buffers)
    {
      this->Copies.Draw(caster.Actor, renderer);
    }
    resident = resident || (caster.Buffers && !caster.Translucent);
  }
  if (resident)
  {
    ostate->vtkglDisable(GL_CULL_FACE);
    this->Depth.Begin(frame.Window);
    for (const Caster& caster : key.Casters)
    {
      if (caster.Buffers && !caster.Translucent)
      {
        const std::array<float, 16> m =
          ClipFromModel(key.ClipFromWorld, caster.Matrix, caster.Buffers->Shift);
        this->Depth.Draw(*caster.Buffers, m.data());
      }
    }
    this->Depth.End();
  }
  if (this->Transmittance.IsAllocated())
  {
    // Cleared in every layer, translucent casters or not: readers look each layer up.
    this->Transmittance.Begin(frame.Window, layer, this->Maps.GetTexture());
    for (const Caster& caster : key.Casters)
    {
      if (caster.Translucent)
      {
        const std::array<float, 16> m =
          ClipFromModel(key.ClipFromWorld, caster.Matrix, caster.Buffers->Shift);
        vtkProperty* property = caster.Actor->GetProperty();
        const double* c = property->GetDiffuseColor();
        const float rgba[4] = { static_cast<float>(c[0]), static_cast<float>(c[1]),
          static_cast<float>(c[2]), static_cast<float>(property->GetOpacity()) };
        this->Transmittance.Draw(*caster.Buffers, m.data(), rgba);
      }
    }
    this->Transmittance.End(frame.Window);
  }
}

}
