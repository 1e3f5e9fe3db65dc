/**
 * TranslucentLighting: VTK's translucent surfaces receive GI. While VTK's translucent step
 * draws, this internal render pass is on the keys of the translucent actors the scan recorded
 * (ActorRecord::Translucent) and adds to each fragment's colour its diffuse colour times the
 * indirect light arriving there, traced by two cones through the voxels
 * (translucent_lighting.glsl); VTK's own colour, blending and order-independent translucency
 * or depth peeling stay as they are.
 */
#ifndef VoxelGITranslucentLighting_h
#define VoxelGITranslucentLighting_h

#include "ConeSettings.h"

#include "vtkOpenGLRenderPass.h" // for the superclass

#include <array>
#include <functional>

class vtkProp;

namespace voxelgi
{
struct Frame;

class TranslucentLighting : public vtkOpenGLRenderPass
{
public:
  static TranslucentLighting* New();
  vtkTypeMacro(TranslucentLighting, vtkOpenGLRenderPass);

  /// Run `draw` (VTK's translucent step) with the frame's translucent actors lit by its
  /// voxels' radiance (none, or indirect light off: as VTK draws them).
  void Draw(const Frame& frame, const std::function<void()>& draw);
  void Render(const vtkRenderState*) override {}

  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override { return this->ShaderStageTime.GetMTime(); }

protected:
  TranslucentLighting();
  ~TranslucentLighting() override;

private:
  TranslucentLighting(const TranslucentLighting&) = delete;
  void operator=(const TranslucentLighting&) = delete;

  /// The view -> grid transforms of the frame's camera.
  void SetTransforms(const Frame& frame);

  ConeTracingInputs Inputs; // while the step draws
  ConeSettings Cones;
  float Intensity = 1.f;                        // IndirectIntensity
  std::array<float, 16> GridFromView{};         // column-major
  std::array<float, 9> GridNormalFromView{};    // column-major
  vtkTimeStamp ShaderStageTime;
};

}

#endif
