// Example viewer: a QVTKOpenGLNativeWidget with voxel GI, the settings panel in a dock, a
// scene chooser and File > Open for .vtp and .obj files.
#ifndef VoxelGIViewerWindow_h
#define VoxelGIViewerWindow_h

#include "vtkNew.h"

#include <QElapsedTimer>
#include <QMainWindow>

class QComboBox;
class QVTKOpenGLNativeWidget;
class vtkGenericOpenGLRenderWindow;
class vtkRenderer;
class vtkVoxelGIPass;
class vtkVoxelGISettingsWidget;

class VoxelGIViewerWindow : public QMainWindow
{
  Q_OBJECT

public:
  explicit VoxelGIViewerWindow(QWidget* parent = nullptr);
  ~VoxelGIViewerWindow() override;

  vtkGenericOpenGLRenderWindow* renderWindow() const { return this->Window; }
  vtkVoxelGIPass* pass() const { return this->Pass; }
  vtkVoxelGISettingsWidget* settings() const { return this->Settings; }
  /// A render after a frame slower than this shows the busy state (default 0.2 s; 0: every
  /// render).
  void setBusyAfter(double seconds) { this->BusyAfter = seconds; }

  /// Built-in scenes: 0 Cornell box, 1 wavelet isosurface, 2 glyph field.
  void showScene(int scene);
  /// Load a .vtp or .obj file into a room with a light.
  bool openFile(const QString& path);

private:
  void resetRenderer();
  /// The busy state: a wait cursor and a status message while a slow frame renders.
  void renderStarted();
  void renderEnded();

  QVTKOpenGLNativeWidget* View = nullptr;
  vtkVoxelGISettingsWidget* Settings = nullptr;
  QComboBox* SceneChooser = nullptr;
  vtkNew<vtkGenericOpenGLRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVoxelGIPass> Pass;
  QElapsedTimer RenderClock;
  double LastFrameSeconds = 1.0; // the first frame compiles shaders and voxelizes: slow
  double BusyAfter = 0.2;
  bool Busy = false;
};

#endif
