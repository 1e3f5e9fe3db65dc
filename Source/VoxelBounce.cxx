#include "VoxelBounce.h"

#include "Frame.h"
#include "LightVoxels.h"
#include "VoxelGIShaders.h"
#include "VoxelMipmap.h"
#include "VoxelizePass.h"
#include "StageIds.h"

#include "vtk_glew.h"


namespace voxelgi
{

bool VoxelBounce::Prepare(const Frame& frame, std::string& error)
{
  this->Cones.Set(frame.Config, frame.Grid.Resolution);
  const bool volumes = frame.Volumes && !frame.Volumes->empty();
  if (!volumes)
  {
    this->Incident.Release();
  }
  else if (this->Incident.Resolution() != frame.Grid.Resolution)
  {
    if (!this->Incident.Allocate(GL_R11F_G11F_B10F, frame.Grid.Resolution))
    {
      error = "could not allocate the volumes' incident light";
      return false;
    }
    this->Incident.Clear(); // bricks the bounce never visits stay dark
  }
  if (!this->Sums.IsAllocated() &&
    !this->Sums.Allocate(sizeof(unsigned int) * (6 * VOXELGI_MAX_BOUNCES + 3)))
  {
    error = "could not allocate the bounces' sums";
    return false;
  }
  return this->Program.BuildOnce(shaders::voxel_bounce_comp, "voxel bounce", error,
    volumes ? "#define VOXELGI_VOLUMES\n" : "");
}

void VoxelBounce::Run(const Frame& frame)
{
  // Bounce and mipmap timings would nest: time them together.
  ScopedStage stage(*frame.Clock, stage::Bounce);
  if (frame.Config.BounceTail)
  {
    // A relight from the direct light starts the sums and the ratio anew; one that continues
    // the last solution (a bounce) keeps the ratio that solution measured.
    const unsigned int zeros[6 * VOXELGI_MAX_BOUNCES + 3] = {};
    const bool anew = frame.Plan.Lights == LightWork::Relight;
    this->Sums.Upload(zeros, sizeof(zeros) - (anew ? 0 : 3 * sizeof(unsigned int)));
  }
  for (int bounce = 1; bounce <= frame.Plan.Bounces; ++bounce)
  {
    this->Bounce(frame, bounce, bounce == frame.Plan.Bounces);
    this->Mipmap.Build(frame.Window);
  }
}

void VoxelBounce::Bounce(const Frame& frame, int index, bool last)
{
  SamplerBindings samplers(frame.Window);
  GLProgram& p = this->Program;
  p.Use(frame.Window);
  // The bounce writes the radiance volume, so it reads only the mipmaps (level >= 1).
  Volume3D& radiance = this->Lighting.GetRadiance();
  SetConeTracingSamplers(p, samplers, radiance, this->Mipmap, 1.0f, this->Cones.StepFactor);
  p.SetInt("voxelAlbedo", samplers.Add(this->Voxels.GetAlbedo()));
  p.SetInt("voxelNormal", samplers.Add(this->Voxels.GetNormal()));
  p.SetInt("voxelDirect", samplers.Add(this->Lighting.GetDirect()));
  if (!(samplers.Complete()))
  {
    return;
  }
  p.SetVec3Array("coneDirections", this->Cones.Count, this->Cones.Directions);
  p.SetInt("coneCount", this->Cones.Count);
  p.SetFloat("coneTanHalf", this->Cones.TanHalf);
  p.SetFloat("maxDistance", this->Cones.MaxDistance);
  p.SetInt("bounceIndex", index);
  // Only a relight from the direct light measures the ratio, from its bounces before the last.
  const bool measures = frame.Config.BounceTail && frame.Plan.Lights == LightWork::Relight &&
    frame.Plan.Bounces >= 3 && !last;
  p.SetInt("bounceSums", measures ? 1 : 0);
  p.SetInt("bounceTail", frame.Config.BounceTail && last ? 1 : 0);
  this->Sums.Bind(VOXELGI_BOUNCE_SUMS_BINDING);
  radiance.BindImage(0, GL_READ_WRITE);
  if (this->Incident.IsAllocated())
  {
    this->Incident.BindImage(1, GL_WRITE_ONLY);
  }
  this->Voxels.GetBrickList().Bind(VOXELGI_BRICK_LIST_BINDING);
  p.DispatchIndirect(this->Voxels.GetBrickList());
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
    GL_SHADER_STORAGE_BARRIER_BIT);
}

void VoxelBounce::ReleaseGraphicsResources(vtkWindow*)
{
  this->Program.Release();
  this->Incident.Release();
  this->Sums.Release();
}

}
