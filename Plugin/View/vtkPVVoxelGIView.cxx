#include "vtkPVVoxelGIView.h"

#include "vtkCommand.h"
#include "vtkObjectFactory.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVoxelGIPass.h"

vtkStandardNewMacro(vtkPVVoxelGIView);

vtkPVVoxelGIView::vtkPVVoxelGIView()
{
  // FXAA post-processes the image the pass composited; keep the GI image as it is.
  this->UseFXAA = false;
  this->StartObserver = this->GetRenderer()->AddObserver(
    vtkCommand::StartEvent, this, &vtkPVVoxelGIView::RenderRanks);
}

vtkPVVoxelGIView::~vtkPVVoxelGIView()
{
  this->GetRenderer()->RemoveObserver(this->StartObserver);
  // The pass stays set on the renderer: its GL resources are freed with the window's
  // (vtkRenderer::ReleaseGraphicsResources), which may already have closed its display here.
  if (this->GIPass)
  {
    this->GIPass->UnRegister(this);
  }
}

void vtkPVVoxelGIView::SetGIPass(vtkVoxelGIPass* pass)
{
  if (pass == this->GIPass)
  {
    return;
  }
  if (this->GIPass)
  {
    this->GIPass->UnRegister(this);
  }
  this->GIPass = pass;
  if (pass)
  {
    pass->Register(this);
  }
  this->SynchronizedRenderers->SetRenderPass(pass);
  this->Modified();
}

void vtkPVVoxelGIView::RenderRanks()
{
  if (this->GIPass)
  {
    this->GIPass->RenderRanks(this->GetRenderer());
  }
}

void vtkPVVoxelGIView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GIPass: " << this->GIPass << "\n";
}
