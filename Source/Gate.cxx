#include "Gate.h"

#include "GLHelpers.h"
#include "SoftwareProfile.h"

#include "vtkCameraPass.h"
#include "vtkImageProcessingPass.h"
#include "vtkObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOutputWindow.h"
#include "vtkRenderer.h"
#include "vtkRenderPassCollection.h"
#include "vtkSSAOPass.h"
#include "vtkSequencePass.h"
#include "vtkShadowMapPass.h"

namespace voxelgi
{

void Gate::Error(Notice notice, const std::string& message)
{
  if (!this->Said.test(notice))
  {
    vtkErrorWithObjectMacro(this->Owner, << message);
    this->Said.set(notice);
  }
}

void Gate::Warning(Notice notice, const std::string& message)
{
  if (!this->Said.test(notice))
  {
    vtkWarningWithObjectMacro(this->Owner, << message);
    this->Said.set(notice);
  }
}

void Gate::Report(const std::string& message, bool error)
{
  if (error)
  {
    vtkErrorWithObjectMacro(this->Owner, << message);
  }
  else
  {
    vtkWarningWithObjectMacro(this->Owner, << message);
  }
}

//------------------------------------------------------------------------------
bool Gate::Serve(vtkRenderPass* pass, vtkRenderer* renderer, bool& renewed)
{
  // Rebuilding for each renderer in turn would cost a full voxelization per renderer per
  // frame, so the first renderer's results are left as they are. (Renderers of two windows
  // take turns, each frame exact: a window's frames are whole.)
  vtkRenderer* owner = this->Renderer;
  renewed = false;
  if (owner && owner != renderer && owner->GetPass() == pass &&
    owner->GetRenderWindow() == renderer->GetRenderWindow())
  {
    this->Error(SharedPass,
      "This pass is set on two renderers of one window; it renders GI for the first only and "
      "VTK's image for the other. Give each renderer a pass of its own (SetVoxelSource lets "
      "them share one voxel grid).");
    return false;
  }
  renewed = owner != renderer;
  this->Renderer = renderer;
  return true;
}

bool Gate::Admit(vtkRenderPass* pass, vtkRenderPass* delegate, vtkRenderer* renderer,
  bool enabled, bool pixelShadows)
{
  if (!delegate)
  {
    this->Error(NoDelegate,
      "No delegate pass: nothing renders VTK's image, so neither VTK's image nor GI is drawn. "
      "Set one (e.g. a vtkRenderStepsPass).");
    return false;
  }
  this->Clear(NoDelegate);
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  // Hardware picking renders through the pass too: it must see VTK's plain render steps.
  const bool admitted = enabled && window && !renderer->GetSelector() &&
    this->Combines(pass, delegate, renderer) && this->CheckContext(window);
  if (admitted)
  {
    this->NoteShadowMapPass(pass, delegate, renderer, pixelShadows);
  }
  return admitted;
}

namespace
{
/// Whether the tree of passes under `root`, as VTK's pass classes show it (camera and image
/// processing passes' delegates, sequences, and `pass`'s `delegate`), holds a
/// vtkShadowMapPass.
bool HasShadowMapPass(vtkRenderPass* root, vtkRenderPass* pass, vtkRenderPass* delegate)
{
  auto below = [&](vtkRenderPass* child) { return HasShadowMapPass(child, pass, delegate); };
  if (!root || vtkShadowMapPass::SafeDownCast(root))
  {
    return root != nullptr;
  }
  if (root == pass)
  {
    return below(delegate);
  }
  if (auto* camera = vtkCameraPass::SafeDownCast(root))
  {
    return below(camera->GetDelegatePass());
  }
  if (auto* processing = vtkImageProcessingPass::SafeDownCast(root))
  {
    return below(processing->GetDelegatePass());
  }
  auto* sequence = vtkSequencePass::SafeDownCast(root);
  vtkRenderPassCollection* passes = sequence ? sequence->GetPasses() : nullptr;
  for (int i = 0; passes && i < passes->GetNumberOfItems(); ++i)
  {
    if (below(vtkRenderPass::SafeDownCast(passes->GetItemAsObject(i))))
    {
      return true;
    }
  }
  return false;
}
}

void Gate::NoteShadowMapPass(
  vtkRenderPass* pass, vtkRenderPass* delegate, vtkRenderer* renderer, bool pixelShadows)
{
  // Inside GI's delegate or around GI, a program's vtkShadowMapPass shades VTK's image with
  // its own shadows; the composite removes the occluded light again from its own maps.
  const bool both = pixelShadows && HasShadowMapPass(renderer->GetPass(), pass, delegate);
  if (!both)
  {
    this->Clear(ShadowMapPass);
    return;
  }
  this->Warning(ShadowMapPass,
    "A vtkShadowMapPass is among the renderer's passes: its shadows stay in VTK's image and "
    "GI's pixel shadows (ConeShadows) darken the same lights' shadows again, with slightly "
    "different edges. Set ConeShadows off to keep VTK's shadows alone (GI adds indirect light "
    "and AO), or set the GI pass in its place: GI's shadow maps cast every scene light's "
    "shadows.");
}

bool Gate::Combines(vtkRenderPass* pass, vtkRenderPass* delegate, vtkRenderer* renderer)
{
  // vtkSSAOPass draws its delegate into a framebuffer of its own whose extra attachments
  // (positions, normals) only VTK's opaque step writes, and blends its result into the
  // framebuffer bound outside it: neither the G-buffer nor the present can sit on either side.
  std::string reason;
  if (vtkSSAOPass::SafeDownCast(delegate))
  {
    reason = "its delegate is a vtkSSAOPass";
  }
  for (vtkRenderPass* outer = renderer->GetPass(); outer && outer != pass && reason.empty();)
  {
    if (vtkSSAOPass::SafeDownCast(outer))
    {
      reason = "it is the delegate of a vtkSSAOPass";
    }
    else if (auto* processing = vtkImageProcessingPass::SafeDownCast(outer))
    {
      outer = processing->GetDelegatePass();
    }
    else if (auto* camera = vtkCameraPass::SafeDownCast(outer))
    {
      outer = camera->GetDelegatePass();
    }
    else
    {
      outer = nullptr;
    }
  }
  if (reason.empty())
  {
    this->Clear(Combination);
    return true;
  }
  this->Error(Combination,
    "Voxel GI cannot run here: " + reason +
      " (screen-space AO needs VTK's own opaque framebuffer). Rendering without GI; the "
      "AmbientOcclusion setting is GI's own occlusion.");
  return false;
}

bool Gate::CheckContext(vtkRenderWindow* window)
{
  // A refused context is checked once too.
  if (this->ContextChecked && window == this->CheckedWindow.GetPointer())
  {
    return this->ContextOk;
  }
  int major = 0, minor = 0;
  ContextVersion(major, minor);
  this->ContextChecked = true;
  this->CheckedWindow = window;
  this->ContextOk = major > 4 || (major == 4 && minor >= 3);
  this->ConservativeRaster = HasExtension("GL_NV_conservative_raster");
  this->RendererName = voxelgi::RendererName();
  this->SoftwareRenderer = voxelgi::IsSoftwareRenderer(this->RendererName);
  if (!this->ContextOk)
  {
    vtkErrorWithObjectMacro(this->Owner,
      << "Voxel GI needs OpenGL 4.3 (compute shaders, image load/store, shader storage "
         "buffers) but this context provides "
      << major << "." << minor << ". Rendering without GI.");
  }
  return this->ContextOk;
}

bool Gate::SoftwareProfileApplies(int profile) const
{
  return voxelgi::SoftwareProfileApplies(profile, this->SoftwareRenderer);
}

bool Gate::SoftwareProfile(int profile, int resolution)
{
  const bool applies = this->SoftwareProfileApplies(profile);
  if (applies && profile == SOFTWARE_PROFILE_AUTO)
  {
    this->Warning(Software,
      "OpenGL runs on the CPU here (" + this->RendererName +
        "): GI runs in its software profile (at most 64^3 voxels, 4 cones traced at a quarter of "
        "the resolution) to answer in about a second. Set SoftwareProfile to Off "
        "for the full settings (tens of seconds a frame).");
  }
  else if (!applies && this->SoftwareRenderer && resolution >= 128 && !this->SaidSlow)
  {
    // Not a warning (nothing is wrong), but minutes of silence look like a hang.
    this->SaidSlow = true;
    vtkOutputWindowDisplayText(("Voxel GI on " + this->RendererName +
      ", a CPU renderer, with SoftwareProfile Off at " + std::to_string(resolution) +
      "^3 voxels: its first frame compiles every shader and builds every volume on the CPU "
      "(a minute or more), later frames take tens of seconds.\n").c_str());
  }
  return applies;
}

//------------------------------------------------------------------------------
bool Gate::ViewportFits(int width, int height)
{
  // Every image of the frame has the viewport's size: beyond GL's limits none can be made.
  const std::string tooLarge = ImageSizeError("the viewport", width, height);
  if (tooLarge.empty())
  {
    this->RefusedSize[0] = this->RefusedSize[1] = 0;
    return true;
  }
  if (this->RefusedSize[0] != width || this->RefusedSize[1] != height)
  {
    vtkErrorWithObjectMacro(this->Owner,
      << "Voxel GI disabled for this frame: " << tooLarge << "; rendering without GI.");
    this->RefusedSize[0] = width;
    this->RefusedSize[1] = height;
  }
  return false;
}

void Gate::Refuse(const Configuration& configuration, const std::string& error)
{
  if (!this->Refused(configuration))
  {
    vtkErrorWithObjectMacro(this->Owner,
      << "Voxel GI disabled: " << error
      << ". Rendering without GI until a setting changes or Invalidate() is called.");
  }
  this->HasRefused = true;
  this->RefusedConfiguration = configuration;
}

}
