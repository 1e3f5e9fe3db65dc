#include "TranslucentLighting.h"

#include "Frame.h"
#include "GLHelpers.h"
#include "LightVoxels.h"
#include "SceneScan.h"
#include "VoxelGIShaders.h"
#include "VoxelMipmap.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

#include <vector>

namespace voxelgi
{

namespace
{
// The cones that gather the diffuse light a translucent surface adds to VTK's colour: each is
// a trace at every fragment of every translucent layer, in every frame (VTK draws its
// translucent step in unchanged frames too). Two of the trace's aperture match six on the
// study's translucent scene (FLIP 0.0889 against 0.0893; one wide cone of 120 degrees: 0.0970,
// it reads what lies behind the surface) at a third of the cost (docs/performance.md).
constexpr int ConeCount = 2;
}

vtkStandardNewMacro(TranslucentLighting);

TranslucentLighting::TranslucentLighting()
{
  this->ShaderStageTime.Modified();
}

TranslucentLighting::~TranslucentLighting() = default;

void TranslucentLighting::Draw(const Frame& frame, const std::function<void()>& draw)
{
  std::vector<vtkProp*> lit;
  for (const ActorRecord& record : frame.Actors ? *frame.Actors : std::vector<ActorRecord>())
  {
    if (record.Translucent && record.Actor)
    {
      lit.push_back(record.Actor);
    }
  }
  this->Intensity = static_cast<float>(frame.Config.IndirectIntensity);
  if (lit.empty() || this->Intensity <= 0.f || !frame.Lighting || !frame.Mipmap)
  {
    draw();
    return;
  }
  SamplerBindings samplers(frame.Window);
  this->Inputs = BindConeTracing(samplers, frame.Lighting->GetRadiance(), *frame.Mipmap, 0.0f,
    static_cast<float>(frame.Config.ConeStepFactor));
  if (!samplers.Complete())
  {
    draw();
    return;
  }
  this->Cones.Set(ConeCount, frame.Config.DiffuseConeAperture, frame.Config.ConeStepFactor,
    frame.Config.MaxTraceDistance * frame.Grid.Resolution);
  this->SetTransforms(frame);
  vtkRenderState keys(frame.Renderer);
  keys.SetPropArrayAndCount(lit.data(), static_cast<int>(lit.size()));
  this->PreRender(&keys);
  draw();
  this->PostRender(&keys);
}

void TranslucentLighting::SetTransforms(const Frame& frame)
{
  vtkNew<vtkMatrix4x4> worldFromView;
  vtkMatrix4x4::Invert(
    frame.Renderer->GetActiveCamera()->GetModelViewTransformMatrix(), worldFromView);
  const double scale = 1.0 / frame.Grid.VoxelSize;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      // grid = (world - origin) / voxel size; column-major out
      const double offset = c == 3 ? -frame.Grid.Origin[r] : 0.0;
      this->GridFromView[4 * c + r] =
        static_cast<float>((worldFromView->GetElement(r, c) + offset) * scale);
      if (c < 3)
      {
        this->GridNormalFromView[3 * c + r] = static_cast<float>(worldFromView->GetElement(r, c));
      }
    }
  }
  this->GridFromView[3] = this->GridFromView[7] = this->GridFromView[11] = 0.f;
  this->GridFromView[15] = 1.f;
}

bool TranslucentLighting::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragment, vtkAbstractMapper* mapper, vtkProp* prop)
{
  // Polydata surfaces; lit ones only (PostReplaceShaderValues): VTK's shader then has the
  // position, normal and diffuse colour the cones start from.
  if (!vtkActor::SafeDownCast(prop) || !vtkOpenGLPolyDataMapper::SafeDownCast(mapper) ||
    fragment.find("//VTK::TCoord::Impl") == std::string::npos)
  {
    return true;
  }
  vtkShaderProgram::Substitute(fragment, "//VTK::System::Dec",
    std::string("//VTK::System::Dec\n") + shaders::translucent_lighting_glsl, false);
  vtkShaderProgram::Substitute(fragment, "//VTK::TCoord::Impl",
    "//VTK::TCoord::Impl\n"
    "#if defined(VOXELGI_LIT)\n"
    "  gl_FragData[0].rgb += diffuseColor * voxelgiIndirect(vertexVC.xyz, normalVCVSOutput);\n"
    "#endif\n",
    false);
  return true;
}

bool TranslucentLighting::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragment, vtkAbstractMapper*, vtkProp*)
{
  // Only where VTK's shader computed them (a lit surface): not known before its replacements.
  if (fragment.find("voxelgiIndirect(") != std::string::npos &&
    fragment.find("vec4 vertexVC") != std::string::npos &&
    fragment.find("normalVCVSOutput") != std::string::npos &&
    fragment.find("vec3 diffuseColor") != std::string::npos)
  {
    vtkShaderProgram::Substitute(
      fragment, "//VTK::System::Dec", "//VTK::System::Dec\n#define VOXELGI_LIT", false);
  }
  return true;
}

bool TranslucentLighting::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  if (!program->IsUniformUsed("voxelgiGridFromView"))
  {
    return true;
  }
  for (int i = 0; i < 7; ++i)
  {
    program->SetUniformi(ConeTracingInputs::SamplerNames[i], this->Inputs.Units[i]);
  }
  program->SetUniformi("voxelIsotropic", this->Inputs.Isotropic);
  program->SetUniformf("voxelMinLevel", this->Inputs.MinLevel);
  program->SetUniformf("coneStepFactor", this->Inputs.StepFactor);
  program->SetUniformMatrix4x4("voxelgiGridFromView", this->GridFromView.data());
  program->SetUniformMatrix3x3("voxelgiGridNormalFromView", this->GridNormalFromView.data());
  program->SetUniform3fv("voxelgiConeDirections", this->Cones.Count,
    reinterpret_cast<const float(*)[3]>(this->Cones.Directions));
  program->SetUniformi("voxelgiConeCount", this->Cones.Count);
  program->SetUniformf("voxelgiConeTanHalf", this->Cones.TanHalf);
  program->SetUniformf("voxelgiMaxDistance", this->Cones.MaxDistance);
  program->SetUniformf("voxelgiIndirectIntensity", this->Intensity);
  return true;
}

}
