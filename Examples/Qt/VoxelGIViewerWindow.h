// Example viewer: a QVTKOpenGLNativeWidget with voxel GI, the settings panel in a dock, a
// scene chooser and File > Open for .vtp and .obj files.
#ifndef VoxelGIViewerWindow_h
#define VoxelGIViewerWindow_h

#include "vtkNew.h"

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

  /// Built-in scenes: 0 Cornell box, 1 wavelet isosurface, 2 glyph field.
  void showScene(int scene);
  /// Load a .vtp or .obj file into a room with a light.
  bool openFile(const QString& path);

private:
  void resetRenderer();

  QVTKOpenGLNativeWidget* View = nullptr;
  vtkVoxelGISettingsWidget* Settings = nullptr;
  QComboBox* SceneChooser = nullptr;
  vtkNew<vtkGenericOpenGLRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVoxelGIPass> Pass;
};

#endif
