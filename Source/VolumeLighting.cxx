#include "VolumeLighting.h"

#include "Frame.h"
#include "GLHelpers.h"
#include "VoxelGIShaders.h"

#include "vtkObjectFactory.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkVolume.h"

#include <algorithm>

namespace voxelgi
{

namespace
{
// Where VTK's ray caster premultiplies a composited sample's colour (vtkVolumeShaderComposer).
const char* const SampleColor = "g_srcColor.rgb *= g_srcColor.a;";
}

vtkStandardNewMacro(VolumeLighting);

VolumeLighting::VolumeLighting()
{
  this->ShaderStageTime.Modified();
}

VolumeLighting::~VolumeLighting() = default;

int VolumeLighting::Draw(const Frame& frame, vtkRenderPass* volumetric, const Volume3D* incident)
{
  std::vector<vtkProp*> lit;
  for (const VolumeRecord& record : frame.Volumes ? *frame.Volumes : std::vector<VolumeRecord>())
  {
    if (record.Volume)
    {
      lit.push_back(record.Volume);
    }
  }
  // Indirect light off: VTK's volumes as VTK draws them.
  this->Intensity = static_cast<float>(frame.Config.IndirectIntensity);
  SamplerBindings samplers(frame.Window);
  this->Unit = incident && !lit.empty() && this->Intensity > 0.f ? samplers.Add(*incident) : -1;
  if (this->Unit < 0 || !samplers.Complete())
  {
    volumetric->Render(frame.State);
    return volumetric->GetNumberOfRenderedProps();
  }
  const double scale = 1.0 / frame.Grid.Size();
  this->GridFromWorld.fill(0.f);
  for (int i = 0; i < 3; ++i)
  {
    this->GridFromWorld[5 * i] = static_cast<float>(scale);
    this->GridFromWorld[12 + i] = static_cast<float>(-frame.Grid.Origin[i] * scale);
  }
  this->GridFromWorld[15] = 1.f;
  vtkRenderState keys(frame.Renderer);
  keys.SetPropArrayAndCount(lit.data(), static_cast<int>(lit.size()));
  this->PreRender(&keys);
  volumetric->Render(frame.State);
  this->PostRender(&keys);
  this->Unit = -1;
  return volumetric->GetNumberOfRenderedProps();
}

bool VolumeLighting::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragment, vtkAbstractMapper*, vtkProp* prop)
{
  // Only volumes the scan resampled (composite, one component) carry this pass.
  if (vtkVolume::SafeDownCast(prop))
  {
    // The ray's set-up only where its declaration went in (PostReplaceShaderValues reads the
    // light only where the set-up did).
    if (vtkShaderProgram::Substitute(fragment, "//VTK::ComputeColor::Dec",
          std::string(shaders::volume_lighting_glsl) + "\n//VTK::ComputeColor::Dec", false))
    {
      vtkShaderProgram::Substitute(
        fragment, "//VTK::Shading::Init", "voxelgiBeginRay();\n//VTK::Shading::Init", false);
    }
  }
  return true;
}

bool VolumeLighting::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragment, vtkAbstractMapper*, vtkProp* prop)
{
  if (vtkVolume::SafeDownCast(prop) && fragment.find("voxelgiBeginRay();") != std::string::npos)
  {
    vtkShaderProgram::Substitute(fragment, SampleColor,
      std::string("g_srcColor.rgb += g_srcColor.rgb * voxelgiIndirect(g_dataPos);\n") +
        SampleColor,
      false);
  }
  return true;
}

bool VolumeLighting::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  if (vtkVolume::SafeDownCast(prop) && program->IsUniformUsed("voxelgiIncident"))
  {
    program->SetUniformi("voxelgiIncident", this->Unit);
    program->SetUniformMatrix4x4("voxelgiGridFromWorld", this->GridFromWorld.data());
    program->SetUniformf("voxelgiIndirectIntensity", this->Intensity);
  }
  return true;
}

}
