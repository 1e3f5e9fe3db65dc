/**
 * VolumeLighting: VTK's volumes receive GI. While VTK's volumetric step draws, this internal
 * render pass is on the keys of the volumes in the voxels (VolumeVoxels) and adds to each ray
 * sample's colour the indirect light arriving there (the last bounce's gather at the volumes'
 * voxels, VoxelBounce) times the sample's colour: isotropic scattering of the light the scene
 * sends it (volume_lighting.glsl). VTK's own colour of the sample stays as it is. The GPU ray
 * caster (vtkGPUVolumeRayCastMapper, vtkSmartVolumeMapper in its GPU modes) takes the code;
 * other volume mappers ignore render passes and draw as without GI.
 */
#ifndef VoxelGIVolumeLighting_h
#define VoxelGIVolumeLighting_h

#include "vtkOpenGLRenderPass.h" // for the superclass

#include <array>
#include <vector>

class vtkProp;
class vtkRenderPass;

namespace voxelgi
{
struct Frame;
class Volume3D;

class VolumeLighting : public vtkOpenGLRenderPass
{
public:
  static VolumeLighting* New();
  vtkTypeMacro(VolumeLighting, vtkOpenGLRenderPass);

  /// Render `volumetric` (VTK's volumetric step) with the frame's volumes lit by
  /// `incident` (null: as VTK draws them); returns the props it drew.
  int Draw(const Frame& frame, vtkRenderPass* volumetric, const Volume3D* incident);
  void Render(const vtkRenderState*) override {}

  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override { return this->ShaderStageTime.GetMTime(); }

protected:
  VolumeLighting();
  ~VolumeLighting() override;

private:
  VolumeLighting(const VolumeLighting&) = delete;
  void operator=(const VolumeLighting&) = delete;

  int Unit = -1;                        // of the incident light while the step draws
  float Intensity = 1.f;                // IndirectIntensity
  std::array<float, 16> GridFromWorld{}; // world -> the grid's texture coordinates
  vtkTimeStamp ShaderStageTime;
};

}

#endif
