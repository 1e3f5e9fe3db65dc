/**
 * @class   vtkPVVoxelGIView
 * @brief   ParaView render view with voxel global illumination.
 *
 * A vtkPVRenderView that renders its geometry through a vtkVoxelGIPass. The pass is a
 * sub-proxy of the view ("Render View (Voxel GI)"), so its settings are properties of the
 * view, generated from the settings table.
 *
 * Client/server: in the builtin session (client and server in one process) the pass sees all
 * the geometry. With several render-server ranks (pvserver or pvbatch under MPI) each rank
 * voxelizes its own piece into one grid fitted to all pieces, the ranks add up their
 * voxelization sums, and every rank lights and traces the merged grid for its own pixels;
 * IceT composites the ranks' images (see vtkVoxelGIPass::GetRankTrafficBytes). IceT skips
 * ranks with nothing in view: the view starts every frame with the pass's collective part on
 * every rank (vtkVoxelGIPass::RenderRanks).
 */
#ifndef vtkPVVoxelGIView_h
#define vtkPVVoxelGIView_h

#include "VoxelGIParaViewViewModule.h" // for export macro
#include "vtkPVRenderView.h"

class vtkVoxelGIPass;

class VOXELGIPARAVIEWVIEW_EXPORT vtkPVVoxelGIView : public vtkPVRenderView
{
public:
  static vtkPVVoxelGIView* New();
  vtkTypeMacro(vtkPVVoxelGIView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The pass that renders the geometry (the view's "VoxelGI" sub-proxy).
   */
  void SetGIPass(vtkVoxelGIPass* pass);
  vtkGetObjectMacro(GIPass, vtkVoxelGIPass);

protected:
  vtkPVVoxelGIView();
  ~vtkPVVoxelGIView() override;

  /// The renderer's StartEvent: the pass's collective part of the frame.
  void RenderRanks();

  vtkVoxelGIPass* GIPass = nullptr;
  unsigned long StartObserver = 0;

private:
  vtkPVVoxelGIView(const vtkPVVoxelGIView&) = delete;
  void operator=(const vtkPVVoxelGIView&) = delete;
};

#endif
