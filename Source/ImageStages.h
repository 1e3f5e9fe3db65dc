/**
 * The per-pixel stages, wired to what they read: GBuffer, ConeTrace, Composite, the voxel
 * debug view and Present, with their release. Trace runs them as the frame plan says.
 */
#ifndef VoxelGIImageStages_h
#define VoxelGIImageStages_h

#include "Composite.h"
#include "ConeTrace.h"
#include "DebugView.h"
#include "GBufferPass.h"
#include "Present.h"

#include "vtkNew.h" // for vtkNew

#include <string>

class vtkWindow;

namespace voxelgi
{
struct Frame;
class LightBlock;
class VoxelGridBlock;

struct ImageStages
{
  vtkNew<GBufferPass> GBuffer;
  ConeTrace Trace{ *GBuffer };
  Composite Compositor{ *GBuffer, Trace };
  DebugView Debug;
  Present Presenter{ Compositor, *GBuffer, Debug };

  /// GBuffer, ConeTrace and Composite (a voxel debug view: DebugView), and Present's
  /// program; false with `error` when one cannot be prepared. The `lights` and `grid`
  /// blocks are bound again after VTK's raster work.
  bool Run(const Frame& frame, LightBlock& lights, VoxelGridBlock& grid, std::string& error);
  void ReleaseGraphicsResources(vtkWindow* window);
};

}

#endif
