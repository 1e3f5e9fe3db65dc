/**
 * ShadowTransmittance stage (shadow_transmittance.vert/.frag): beside each shadow map layer,
 * the light that translucent actors let through, tinted by their colour as much as they are
 * opaque (rgb), and the nearest of them (alpha: one minus its depth), drawn from their
 * GPU-resident triangles (SceneBuffers) after the layer's opaque depth, which hides those
 * behind it. Allocated only
 * while a translucent actor casts shadows; the maps' readers (shadow_maps.glsl) multiply a
 * point's visibility by it where the point lies behind that nearest translucent surface.
 */
#ifndef VoxelGIShadowTransmittance_h
#define VoxelGIShadowTransmittance_h

#include "GLHelpers.h"
#include "SceneBuffers.h"

#include <cstddef>
#include <string>

class vtkOpenGLRenderWindow;

namespace voxelgi
{

class ShadowTransmittance
{
public:
  /// Build the program and allocate `layers` layers of `size` texels (none: free them;
  /// context current); false with `error` when either fails.
  bool Prepare(int size, int layers, std::string& error);
  bool IsAllocated() const { return this->Texture != 0; }
  std::size_t Bytes() const;

  /// Clear `layer` to full transmittance and bind it for the draws, depth-tested against
  /// `depthTexture`'s same layer (the opaque casters' depth, left unwritten); End unbinds.
  void Begin(vtkOpenGLRenderWindow* window, int layer, unsigned int depthTexture);
  /// Draw a translucent actor's triangles; `clipFromModel` (column-major) takes its shifted
  /// model coordinates to the layer's clip space, `rgba` its diffuse colour and opacity (used
  /// where its scalars do not colour it).
  void Draw(const SceneBuffers::Entry& buffers, const float* clipFromModel, const float* rgba);
  void End(vtkOpenGLRenderWindow* window);

  /// Bind the layers (or, unallocated, a texel of full transmittance) to `program`'s (in use)
  /// `shadowTransmittance` sampler.
  void Bind(GLProgram& program, SamplerBindings& samplers) const;
  void ReleaseGraphicsResources();

private:
  void Release();

  GLProgram Program;
  unsigned int VertexArray = 0; // empty: the vertices are pulled from the buffers
  unsigned int Texture = 0;     // RGBA16F array
  unsigned int Framebuffer = 0;
  unsigned int Clear = 0;       // one texel, for readers while nothing is translucent
  int Size = 0;
  int Layers = 0;
};

}

#endif
