/**
 * ShadowDepth stage (shadow_depth.vert): shadow map depth of the actors whose triangles are
 * GPU-resident (SceneBuffers, read for compute voxelization), one GL draw per actor and map
 * layer from those buffers, where a draw through a copy of VTK's mapper costs tens of
 * microseconds of CPU each (ShadowMaps draws the other actors that way).
 */
#ifndef VoxelGIShadowDepth_h
#define VoxelGIShadowDepth_h

#include "GLHelpers.h"
#include "SceneBuffers.h"

#include <string>

class vtkOpenGLRenderWindow;

namespace voxelgi
{

class ShadowDepth
{
public:
  /// Build the program (context current).
  bool Prepare(std::string& error);
  /// Bind the program for the draws of one layer; End unbinds it.
  void Begin(vtkOpenGLRenderWindow* window);
  /// Draw `buffers`' triangles into the bound layer; `clipFromModel` (column-major) takes
  /// their shifted model coordinates to the layer's clip space.
  void Draw(const SceneBuffers::Entry& buffers, const float* clipFromModel);
  void End();
  void ReleaseGraphicsResources();

private:
  GLProgram Program;
  unsigned int VertexArray = 0; // empty: the vertices are pulled from the buffers
};

}

#endif
