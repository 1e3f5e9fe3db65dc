/**
 * ConeTrace stage (cone_trace.comp, a compute dispatch in 8x8 tiles): per pixel of the G-buffer, at the trace resolution
 * (TraceScale: TraceResolution of the image's, halved above MaxTraceMegapixels), diffuse cones over the normal's hemisphere (indirect
 * diffuse and AO), one specular cone whose aperture follows the specular power, and a narrow
 * cone toward each light for its shadow, through the radiance mipmaps (a scene light with a
 * shadow map of the frame's, Frame::Shadows, is looked up there instead). The diffuse cone
 * set turns by a quarter turn from pixel to pixel of each 2 x 2 block (Composite gathers over
 * the four turns). Outputs: indirect light + AO, and the part of VTK's direct shading the
 * shadows take away.
 *
 * Temporal reuse: in a frame where only the camera changed (Frame::CameraOnly), one tile in
 * four (rotating) is traced and the others take last frame's result at the surface's
 * reprojected position, unless the surface there differs (position, normal, or, for specular
 * surfaces, the view direction): then they are listed and traced by a second, indirect
 * dispatch over the list alone. So every pixel is fresh at least every fourth frame and
 * nothing is reused across a change of the surface it belongs to.
 */
#ifndef VoxelGIConeTrace_h
#define VoxelGIConeTrace_h

#include "ConeSettings.h"
#include "GLHelpers.h" // for StorageBuffer

#include "vtkSmartPointer.h"  // for vtkSmartPointer
#include "vtkTextureObject.h" // for vtkSmartPointer

#include <array>
#include <string>

class vtkWindow;

namespace voxelgi
{
struct Frame;
class GBufferPass;

class ConeTrace
{
public:
  explicit ConeTrace(const GBufferPass& gbuffer);

  /// Size the traced images for the frame's viewport and trace resolution; build the program.
  bool Prepare(const Frame& frame, std::string& error);
  void Run(const Frame& frame);
  void ReleaseGraphicsResources(vtkWindow* window);

  /// Indirect rgb + AO, and occluded direct rgb, at the trace resolution.
  vtkTextureObject* GetIndirect() const { return this->History[this->Current].Indirect; }
  vtkTextureObject* GetShadowed() const { return this->History[this->Current].Shadowed; }
  /// Whether the last Run reused the frame before (a fraction of the tiles traced).
  bool GetReused() const { return this->Reused; }

private:
  /// One frame's results, and the surface (NDC depth, encoded normal) they belong to.
  struct TraceImages
  {
    vtkSmartPointer<vtkTextureObject> Indirect;
    vtkSmartPointer<vtkTextureObject> Shadowed;
    vtkSmartPointer<vtkTextureObject> Surface;
  };

  /// This frame's uniforms; keeps its camera matrices for the next frame.
  void SetUniforms(const Frame& frame);
  /// The previous frame's camera for reprojection (used when `reuse`); keeps this frame's eye.
  void SetHistoryUniforms(const Frame& frame, bool reuse);

  const GBufferPass& GBuffer;
  ConeSettings Cones;
  GLProgram Program;
  bool WithShadowMaps = false; // the program's variant
  std::array<TraceImages, 2> History; // this frame's and the previous frame's
  // Dispatch arguments, count and pixels of reused tiles to trace again (cone_trace.comp).
  StorageBuffer RetraceList;
  int Current = 0;
  bool HistoryValid = false;
  bool Reused = false;
  int Phase = 0;
  // The camera of the last traced frame (grid coordinates).
  float PreviousGridFromNDC[16] = {};
  float PreviousNDCFromGrid[16] = {};
  float PreviousEye[4] = {};
};

}

#endif
