#include "LightBlock.h"

#include "VoxelGrid.h"

#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

namespace voxelgi
{

namespace
{
bool Finite(const double* v, int n)
{
  for (int i = 0; i < n; ++i)
  {
    if (!std::isfinite(v[i]))
    {
      return false;
    }
  }
  return true;
}

/// What makes a light unusable (empty: nothing): VTK's shading of such a light is undefined.
std::string InvalidPart(vtkLight* light)
{
  const double* color = light->GetDiffuseColor();
  if (!(light->GetIntensity() > 0.0) || !std::isfinite(light->GetIntensity()))
  {
    return "a negative or non-finite intensity";
  }
  if (!Finite(color, 3) || color[0] < 0.0 || color[1] < 0.0 || color[2] < 0.0)
  {
    return "a negative or non-finite colour";
  }
  double position[3], focal[3];
  light->GetTransformedPosition(position);
  light->GetTransformedFocalPoint(focal);
  if (!Finite(position, 3) || !Finite(focal, 3))
  {
    return "a non-finite position or focal point";
  }
  const double* attenuation = light->GetAttenuationValues();
  if (light->GetPositional() &&
    (!Finite(attenuation, 3) || attenuation[0] < 0.0 || attenuation[1] < 0.0 ||
      attenuation[2] < 0.0))
  {
    return "negative or non-finite attenuation";
  }
  if (light->GetPositional() && attenuation[0] == 0.0 && attenuation[1] == 0.0 &&
    attenuation[2] == 0.0)
  {
    // VTK divides by the attenuation polynomial: its image of such a light is 0/0 and inf.
    return "attenuation (0, 0, 0)";
  }
  const double shape[2] = { light->GetExponent(), light->GetConeAngle() };
  if (light->GetPositional() && !Finite(shape, 2))
  {
    return "a non-finite spot exponent or cone angle";
  }
  return std::string();
}

// Angle between two vectors (first three components), degrees; 0 when either is zero.
double AngleBetween(const float* a, const float* b, float centre)
{
  double u[3], v[3];
  for (int i = 0; i < 3; ++i)
  {
    u[i] = a[i] - centre;
    v[i] = b[i] - centre;
  }
  if (vtkMath::Normalize(u) == 0.0 || vtkMath::Normalize(v) == 0.0)
  {
    return 0.0;
  }
  return vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(u, v));
}
}

void LightBlock::Pack(vtkLight* light, const VoxelGrid& grid, Light& l)
{
  double position[3], focal[3];
  light->GetTransformedPosition(position);
  light->GetTransformedFocalPoint(focal);
  double direction[3] = { focal[0] - position[0], focal[1] - position[1], focal[2] - position[2] };
  if (vtkMath::Normalize(direction) == 0.0)
  {
    direction[2] = -1.0;
  }
  const glm::dvec3 p = grid.ToVoxel(glm::dvec3(position[0], position[1], position[2]));
  const bool positional = light->GetPositional() != 0;
  for (int a = 0; a < 3; ++a)
  {
    l.position[a] = static_cast<float>(p[a]);
    l.direction[a] = static_cast<float>(direction[a]);
    l.color[a] = static_cast<float>(light->GetDiffuseColor()[a] * light->GetIntensity());
    l.attenuation[a] = static_cast<float>(light->GetAttenuationValues()[a]);
  }
  l.position[3] = positional ? 1.0f : 0.0f;
  // VTK treats positional lights with a cone angle below 90 degrees as spots.
  const double cone = light->GetConeAngle();
  l.direction[3] = (positional && cone < 90.0)
    ? static_cast<float>(std::cos(vtkMath::RadiansFromDegrees(cone)))
    : -2.0f;
  l.color[3] = static_cast<float>(light->GetExponent());
  l.attenuation[3] = light->LightTypeIsHeadlight() ? 1.0f : 0.0f;
}

bool LightBlock::Gather(
  vtkRenderer* renderer, const VoxelGrid& grid, std::vector<std::string>& warnings)
{
  int dropped = 0, invalid = 0;
  std::set<std::string> reasons;
  // VTK creates its automatic headlight and places headlights and camera lights while
  // rendering; do both before reading the lights, or the first frame would see none.
  if (renderer->GetAutomaticLightCreation() && renderer->GetLights()->GetNumberOfItems() == 0)
  {
    renderer->CreateLight();
  }
  renderer->UpdateLightsGeometryToFollowCamera();
  Block block{};
  int count = 0;
  this->Used.clear();
  this->Follows.fill(false);
  this->Centre = 0.5f * static_cast<float>(grid.Resolution);
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch() || light->GetIntensity() == 0.0)
    {
      continue;
    }
    const std::string reason = InvalidPart(light);
    if (!reason.empty())
    {
      ++invalid;
      reasons.insert(reason);
      continue;
    }
    if (count == MaxLights)
    {
      ++dropped;
      continue;
    }
    this->Used.push_back(light);
    this->Follows[count] = !light->LightTypeIsSceneLight();
    Pack(light, grid, block.voxelLights[count++]);
  }
  block.voxelLightInfo[0] = count;
  block.voxelLightInfo[1] = renderer->GetTwoSidedLighting() ? 1 : 0;
  if (invalid > 0 && !this->WarnedInvalid)
  {
    std::string list;
    for (const std::string& reason : reasons)
    {
      list += (list.empty() ? "" : ", ") + reason;
    }
    warnings.push_back(std::to_string(invalid) + " light(s) with " + list +
      " are left out of the GI.");
    this->WarnedInvalid = true;
  }
  if (dropped > 0 && !this->WarnedDropped)
  {
    warnings.push_back("Voxel GI uses the first " + std::to_string(MaxLights) + " lights; " +
      std::to_string(dropped) + " more are left out of the GI.");
    this->WarnedDropped = true;
  }
  const bool changed = !this->HaveUploaded || std::memcmp(&block, &this->Uploaded, sizeof(Block)) != 0;
  this->Data = block;
  this->Count = count;
  return changed;
}

void LightBlock::Bind()
{
  if (!this->Buffer.IsAllocated())
  {
    this->Buffer.Allocate(sizeof(Block));
    this->HaveUploaded = false;
  }
  if (!this->HaveUploaded || std::memcmp(&this->Data, &this->Uploaded, sizeof(Block)) != 0)
  {
    this->Buffer.Upload(&this->Data, sizeof(Block));
    this->Uploaded = this->Data;
    this->HaveUploaded = true;
  }
  this->Buffer.BindUniform(VOXELGI_LIGHT_BLOCK_BINDING);
}

void LightBlock::MarkLit()
{
  this->Lit = this->Data;
  this->LitFollows = this->Follows;
  this->HaveLit = true;
}

double LightBlock::CameraTurnSinceLit() const
{
  constexpr double never = std::numeric_limits<double>::infinity();
  if (!this->HaveLit || this->Follows != this->LitFollows)
  {
    return never;
  }
  // The current lights with the lit ones' places for those that follow the camera: equal to
  // the lit lights when nothing but those places changed.
  Block placed = this->Data;
  double turn = 0.0;
  for (int l = 0; l < this->Count; ++l)
  {
    if (!this->Follows[l])
    {
      continue;
    }
    const Light& now = this->Data.voxelLights[l];
    const Light& then = this->Lit.voxelLights[l];
    turn = std::max(turn, AngleBetween(now.direction.v, then.direction.v, 0.0f));
    if (now.position[3] != 0.0f)
    {
      turn = std::max(turn, AngleBetween(now.position.v, then.position.v, this->Centre));
    }
    std::copy(then.position.v, then.position.v + 3, placed.voxelLights[l].position.v);
    std::copy(then.direction.v, then.direction.v + 3, placed.voxelLights[l].direction.v);
  }
  return std::memcmp(&placed, &this->Lit, sizeof(Block)) == 0 ? turn : never;
}

void LightBlock::ReleaseGraphicsResources(vtkWindow*)
{
  this->Buffer.Release();
  this->HaveUploaded = false;
  this->HaveLit = false;
}

}
