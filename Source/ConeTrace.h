/**
 * ConeTrace stage (cone_trace.comp, a compute dispatch in 8x8 tiles): per pixel of the G-buffer, at the trace resolution
 * (TraceResolution of the image's), diffuse cones over the normal's hemisphere (indirect
 * diffuse and AO), one specular cone whose aperture follows the specular power, and a narrow
 * cone toward each light for soft shadows, through the radiance mipmaps. Outputs: indirect
 * light + AO, and the part of VTK's direct shading the shadow cones find occluded.
 */
#ifndef VoxelGIConeTrace_h
#define VoxelGIConeTrace_h

#include "ConeTracing.h"

#include "vtkSmartPointer.h"  // for vtkSmartPointer
#include "vtkTextureObject.h" // for vtkSmartPointer

#include <string>

class vtkWindow;

namespace voxelgi
{
struct Frame;
class GBufferPass;
class LightVoxels;
class VoxelMipmap;

class ConeTrace
{
public:
  ConeTrace(const GBufferPass& gbuffer, const LightVoxels& lighting, const VoxelMipmap& mipmap);

  /// Size the traced images for the frame's viewport and trace resolution; build the program.
  bool Prepare(const Frame& frame, std::string& error);
  void Run(const Frame& frame);
  void ReleaseGraphicsResources(vtkWindow* window);

  /// Indirect rgb + AO, and occluded direct rgb, at the trace resolution.
  vtkTextureObject* GetIndirect() const { return this->Indirect; }
  vtkTextureObject* GetShadowed() const { return this->Shadowed; }

private:
  void SetUniforms(const Frame& frame);

  const GBufferPass& GBuffer;
  const LightVoxels& Lighting;
  const VoxelMipmap& Mipmap;
  ConeSettings Cones;
  ComputeProgram Program;
  vtkSmartPointer<vtkTextureObject> Indirect;
  vtkSmartPointer<vtkTextureObject> Shadowed;
};

}

#endif
