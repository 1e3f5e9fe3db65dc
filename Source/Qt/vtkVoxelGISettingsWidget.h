/**
 * @class   vtkVoxelGISettingsWidget
 * @brief   Qt panel for every setting of a vtkVoxelGIPass.
 *
 * The panel builds its controls from the settings table (vtkVoxelGISettings, generated from
 * Source/VoxelGISettings.json): a check box per boolean, a spin box with the setting's range
 * per number (stepping through powers of two where the setting takes only those), a combo box
 * per enumeration, grouped (Voxelization, Lighting, Cones, Debug view, Performance) with the
 * settings' documentation as tooltips, and a "Reset to defaults" button. It stays in sync
 * both ways: editing a control sets the pass, and changes made to the pass from code (its
 * ModifiedEvent) update the controls. With a render window given, a read-out of the last
 * frame's stages (ran or skipped, milliseconds) refreshes after every render.
 */
#ifndef vtkVoxelGISettingsWidget_h
#define vtkVoxelGISettingsWidget_h

#include "VoxelGIQtExport.h"
#include "vtkRenderWindow.h" // for vtkWeakPointer<vtkRenderWindow>
#include "vtkWeakPointer.h"  // for the observed window

#include <QMap>
#include <QStringList>
#include <QWidget>

class QLabel;
class vtkCallbackCommand;
class vtkVoxelGIPass;

class VOXELGIQT_EXPORT vtkVoxelGISettingsWidget : public QWidget
{
  Q_OBJECT

public:
  explicit vtkVoxelGISettingsWidget(QWidget* parent = nullptr);
  ~vtkVoxelGISettingsWidget() override;

  /// The pass whose settings the panel shows and edits (nullptr to unbind).
  void setPass(vtkVoxelGIPass* pass);
  vtkVoxelGIPass* pass() const { return this->Pass; }

  /// Refresh the stage read-out after each render of this window.
  void setRenderWindow(vtkRenderWindow* window);

  /// The settings shown, in table order, and the control of one of them.
  QStringList settingNames() const { return this->Names; }
  QWidget* control(const QString& name) const { return this->Controls.value(name, nullptr); }

public Q_SLOTS:
  /// Set every setting of the pass to its default.
  void resetToDefaults();
  /// Read the pass's settings into the controls.
  void updateControls();
  /// Read the last frame's stages into the read-out.
  void updateTimings();

Q_SIGNALS:
  /// A control changed a setting of the pass.
  void settingChanged(const QString& name, double value);
  /// resetToDefaults() changed settings of the pass (once, however many changed).
  void defaultsRestored();

private:
  /// The control of setting `i` (named `name`) for its type, wired to set the pass.
  QWidget* createControl(int i, const QString& name);
  void apply(const QString& name, double value);
  /// apply() for a control that shows `decimals` decimals: a value finer than it shows
  /// (0.0004 as 0.000) stays unless what is shown changes (Enter on an unedited control).
  void applyShown(const QString& name, double value, int decimals);

  vtkVoxelGIPass* Pass = nullptr;
  // Observed, not owned: the viewer may delete its window before this widget.
  vtkWeakPointer<vtkRenderWindow> Window;
  vtkCallbackCommand* PassObserver = nullptr;
  vtkCallbackCommand* WindowObserver = nullptr;
  unsigned long PassTag = 0;
  unsigned long WindowTag = 0;
  QStringList Names;
  QMap<QString, QWidget*> Controls;
  QLabel* Timings = nullptr;
  bool Updating = false;
};

#endif
