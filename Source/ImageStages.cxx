#include "ImageStages.h"

#include "Frame.h"
#include "LightBlock.h"
#include "VoxelGridBlock.h"

namespace voxelgi
{

bool ImageStages::Run(
  const Frame& frame, LightBlock& lights, VoxelGridBlock& grid, std::string& error)
{
  const bool voxelView = frame.Plan.VoxelView;
  const bool ok = voxelView ? this->Debug.Prepare(frame, error)
                            : this->GBuffer->Prepare(frame, error) &&
      this->Trace.Prepare(frame, error) && this->Compositor.Prepare(frame, error);
  if (!ok || !this->Presenter.Prepare(frame, error))
  {
    return false;
  }
  if (voxelView)
  {
    grid.Bind(frame.Grid);
    this->Debug.Run(frame);
    return true;
  }
  this->GBuffer->Run(frame);
  // VTK's raster work came in between: bind the blocks again before the dispatches.
  lights.Bind();
  grid.Bind(frame.Grid);
  this->Trace.Run(frame);
  this->Compositor.Run(frame);
  return true;
}

void ImageStages::ReleaseGraphicsResources(vtkWindow* window)
{
  this->GBuffer->ReleaseGraphicsResources(window);
  this->Trace.ReleaseGraphicsResources(window);
  this->Compositor.ReleaseGraphicsResources(window);
  this->Debug.ReleaseGraphicsResources(window);
  this->Presenter.ReleaseGraphicsResources(window);
}

}
