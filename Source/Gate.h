/**
 * The gate: whether GI may run in a frame at all, and the pass's refusals and once-only
 * notices. It holds what the pass has said (so that each problem is said once, and again
 * only after it went away) and the configuration it refused (GI stays off, silently, until a
 * setting, the scene's emission or the viewport changes). Messages are the pass's own
 * (vtkErrorMacro / vtkWarningMacro of `owner`), so that its observers see them.
 */
#ifndef VoxelGIGate_h
#define VoxelGIGate_h

#include "vtkType.h"        // for vtkMTimeType
#include "vtkWeakPointer.h" // for vtkWeakPointer

#include <bitset>
#include <string>

class vtkObject;
class vtkOpenGLRenderWindow;
class vtkRenderPass;
class vtkRenderWindow;
class vtkRenderer;

namespace voxelgi
{

/// The configuration a frame runs with, as refusals are remembered: the settings' time, the
/// scene's emission and the viewport.
struct Configuration
{
  vtkMTimeType Settings = 0;
  bool Emission = false;
  int Width = 0;
  int Height = 0;
  bool operator==(const Configuration& o) const
  {
    return Settings == o.Settings && Emission == o.Emission && Width == o.Width &&
      Height == o.Height;
  }
};

class Gate
{
public:
  explicit Gate(vtkObject* owner)
    : Owner(owner)
  {
  }

  /// Problems said once, until they go away (Clear).
  enum Notice
  {
    NoDelegate,
    SharedPass,
    Combination,
    ShadowMapPass,
    Software,
    Unlit,
    Source,
    SourceGone,
    OtherRank,
    NoticeCount
  };
  /// Say `message` as an error (or a warning) unless `notice` was said and not cleared since.
  void Error(Notice notice, const std::string& message);
  void Warning(Notice notice, const std::string& message);
  void Clear(Notice notice) { this->Said.reset(notice); }
  /// Say `message` as an error or a warning, every time.
  void Report(const std::string& message, bool error);

  /// Whether `pass` serves `renderer`: one pass keeps the voxels and images of one renderer;
  /// a second renderer of the same window that has the pass gets VTK's image (said once).
  /// `renewed`: the pass now serves a renderer it did not serve last frame.
  bool Serve(vtkRenderPass* pass, vtkRenderer* renderer, bool& renewed);
  /// Whether GI can run with `delegate` in `renderer` this frame: a delegate (else said
  /// once), `enabled`, a GL window, not picking, the passes around this one hold GI, and
  /// OpenGL 4.3. `pixelShadows`: the pass darkens the lights' shadows in the pixels (said
  /// once when a program's vtkShadowMapPass darkens them too).
  bool Admit(vtkRenderPass* pass, vtkRenderPass* delegate, vtkRenderer* renderer, bool enabled,
    bool pixelShadows);
  /// Whether the context has GL_NV_conservative_raster (checked with the context).
  bool HasConservativeRaster() const { return this->ConservativeRaster; }
  /// Whether the software profile applies with the setting `profile` (SOFTWARE_PROFILE_*) on
  /// the context checked last.
  bool SoftwareProfileApplies(int profile) const;
  /// SoftwareProfileApplies; chosen by AUTO, it is said once; turned off on a software
  /// renderer at `resolution` 128 or more, that the first frame takes long is said once (as
  /// text, not as a warning).
  bool SoftwareProfile(int profile, int resolution);
  /// Whether a viewport of `width` x `height` fits GL's image size limits (said once a size).
  bool ViewportFits(int width, int height);

  /// A stage could not be prepared in `configuration`: say why (once for it).
  void Refuse(const Configuration& configuration, const std::string& error);
  /// Try the refused configuration again (Invalidate(): the program says things changed).
  void Retry() { this->HasRefused = false; }
  /// Whether `configuration` was refused before.
  bool Refused(const Configuration& configuration) const
  {
    return this->HasRefused && this->RefusedConfiguration == configuration;
  }

  /// The window's resources are gone: check the next context again.
  void ReleaseGraphicsResources() { this->ContextChecked = false; }

private:
  bool Combines(vtkRenderPass* pass, vtkRenderPass* delegate, vtkRenderer* renderer);
  void NoteShadowMapPass(vtkRenderPass* pass, vtkRenderPass* delegate, vtkRenderer* renderer,
    bool pixelShadows);
  bool CheckContext(vtkRenderWindow* window);

  vtkObject* Owner;
  std::bitset<NoticeCount> Said;
  vtkWeakPointer<vtkRenderer> Renderer; // the renderer the pass's voxels and images belong to
  bool ContextChecked = false;
  bool ContextOk = false;
  bool ConservativeRaster = false;
  bool SoftwareRenderer = false;
  bool SaidSlow = false; // that a software renderer without the profile takes long
  std::string RendererName; // the context's GL_RENDERER
  vtkWeakPointer<vtkRenderWindow> CheckedWindow; // the window whose context was checked
  int RefusedSize[2] = { 0, 0 }; // the viewport size last refused as too large
  bool HasRefused = false;
  Configuration RefusedConfiguration;
};

}

#endif
