// QtTest for the settings panel and the example viewer (under Xvfb, xcb platform):
// the panel lists exactly the settings table; its controls set the pass; a power-of-two
// setting's control offers only powers of two; labels and tooltips say range and default;
// controls of settings the pass ignores are disabled; changes of the pass update the
// controls; reset restores the defaults; the viewer starts at the defaults, shows a busy
// state during a slow frame and a timing read-out; and its render area matches its baseline image
// (VOXELGI_BASELINE, through vtkTesting, rendered image left in VOXELGI_TEMP).
#include "VoxelGIViewerWindow.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGISettings.h"
#include "vtkVoxelGISettingsWidget.h"

#include "QVTKOpenGLNativeWidget.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkGenericOpenGLRenderWindow.h"
#include "vtkNew.h"
#include "vtkTesting.h"
#include "vtkWindowToImageFilter.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QSurfaceFormat>
#include <QtTest>

#include <utility>

class TestVoxelGIQt : public QObject
{
  Q_OBJECT

private Q_SLOTS:
  void panelListsTheSettingsTable()
  {
    vtkVoxelGISettingsWidget panel;
    QStringList table;
    for (int i = 0; i < vtkVoxelGISettings::GetNumberOfSettings(); ++i)
    {
      table << vtkVoxelGISettings::GetName(i);
    }
    QCOMPARE(panel.settingNames(), table);
    QVERIFY(table.contains("VoxelResolution") && table.contains("DebugView"));
    for (const QString& name : table)
    {
      QVERIFY2(!panel.control(name)->toolTip().isEmpty(), qPrintable(name + " has no tooltip"));
    }
  }

  void labelsAndTooltipsSayRangeAndDefault()
  {
    vtkVoxelGISettingsWidget panel;
    QWidget* resolution = panel.control("VoxelResolution");
    auto* form = qobject_cast<QFormLayout*>(resolution->parentWidget()->layout());
    QVERIFY(form != nullptr);
    auto* label = qobject_cast<QLabel*>(form->labelForField(resolution));
    QVERIFY(label != nullptr);
    QCOMPARE(label->text(), QString("Voxel resolution"));
    QCOMPARE(label->toolTip(), resolution->toolTip());
    QVERIFY2(resolution->toolTip().endsWith("Range: 16 to 512, powers of two. Default: 128."),
      qPrintable(resolution->toolTip()));
    QVERIFY(panel.control("UpdatePolicy")
              ->toolTip()
              .endsWith("Values: OnChange, EveryFrame, EveryNFrames, OnDemand. Default: OnChange."));
    QVERIFY(panel.control("Enabled")->toolTip().endsWith("Default: on."));
    auto* hardware = qobject_cast<QLabel*>(form->labelForField(panel.control("HardwareConservativeRaster")));
    QCOMPARE(hardware->text(), QString("Hardware conservative raster"));
  }

  void settingsThePassIgnoresAreDisabled()
  {
    vtkNew<vtkVoxelGIPass> pass;
    vtkVoxelGISettingsWidget panel;
    panel.setPass(pass);
    QVERIFY(!panel.control("UpdateInterval")->isEnabled()); // OnChange by default
    pass->SetUpdatePolicy(vtkVoxelGIPass::UPDATE_EVERY_N_FRAMES);
    QVERIFY(panel.control("UpdateInterval")->isEnabled());
    QVERIFY(panel.control("ShadowMapResolution")->isEnabled());
    pass->SetLightOcclusion(vtkVoxelGIPass::LIGHT_OCCLUSION_VOXEL_SHADOWS);
    QVERIFY(!panel.control("ShadowMapResolution")->isEnabled());
    pass->SetConeShadows(0);
    QVERIFY(!panel.control("ShadowConeAperture")->isEnabled());
  }

  void controlsSetThePass()
  {
    vtkNew<vtkVoxelGIPass> pass;
    vtkVoxelGISettingsWidget panel;
    panel.setPass(pass);
    qobject_cast<QSpinBox*>(panel.control("Bounces"))->setValue(5);
    QCOMPARE(pass->GetBounces(), 5);
    qobject_cast<QCheckBox*>(panel.control("ConeShadows"))->setChecked(false);
    QCOMPARE(pass->GetConeShadows(), 0);
    qobject_cast<QComboBox*>(panel.control("DebugView"))->setCurrentIndex(vtkVoxelGIPass::DEBUG_VIEW_INDIRECT);
    QCOMPARE(pass->GetDebugView(), static_cast<int>(vtkVoxelGIPass::DEBUG_VIEW_INDIRECT));
    qobject_cast<QDoubleSpinBox*>(panel.control("IndirectIntensity"))->setValue(2.5);
    QCOMPARE(pass->GetIndirectIntensity(), 2.5);
    // the spin box follows the setting's range
    auto* resolution = qobject_cast<QSpinBox*>(panel.control("VoxelResolution"));
    QCOMPARE(resolution->minimum(), 16);
    QCOMPARE(resolution->maximum(), 512);
  }

  void powerOfTwoControlOffersOnlyPowersOfTwo()
  {
    vtkNew<vtkVoxelGIPass> pass;
    vtkVoxelGISettingsWidget panel;
    panel.setPass(pass);
    auto* resolution = qobject_cast<QSpinBox*>(panel.control("VoxelResolution"));
    QCOMPARE(resolution->value(), 128);
    resolution->stepBy(1);
    QCOMPARE(resolution->value(), 256);
    resolution->stepBy(-2);
    QCOMPARE(resolution->value(), 64);
    resolution->stepBy(10);
    QCOMPARE(resolution->value(), 512);
    QCOMPARE(pass->GetVoxelResolution(), 512);
    // typed values end at the power of two the pass rounds them to (ties round up)
    const std::pair<const char*, int> typed[] = { { "129", 128 }, { "192", 256 }, { "1", 16 } };
    for (const auto& t : typed)
    {
      resolution->selectAll();
      QTest::keyClicks(resolution, t.first);
      QTest::keyClick(resolution, Qt::Key_Return);
      QCOMPARE(resolution->value(), t.second);
      QCOMPARE(resolution->text(), QString::number(t.second));
      QCOMPARE(pass->GetVoxelResolution(), t.second);
    }
  }

  void passUpdatesControls()
  {
    vtkNew<vtkVoxelGIPass> pass;
    vtkVoxelGISettingsWidget panel;
    panel.setPass(pass);
    pass->SetVoxelResolution(256);
    pass->SetAmbientOcclusionStrength(0.9);
    pass->SetLightOcclusionToShadowMaps();
    pass->EnabledOff();
    QCOMPARE(qobject_cast<QSpinBox*>(panel.control("VoxelResolution"))->value(), 256);
    QCOMPARE(qobject_cast<QDoubleSpinBox*>(panel.control("AmbientOcclusionStrength"))->value(), 0.9);
    QCOMPARE(qobject_cast<QComboBox*>(panel.control("LightOcclusion"))->currentIndex(),
      static_cast<int>(vtkVoxelGIPass::LIGHT_OCCLUSION_SHADOW_MAPS));
    QCOMPARE(qobject_cast<QCheckBox*>(panel.control("Enabled"))->isChecked(), false);
  }

  void enterKeepsValuesNobodyEdited()
  {
    // Values finer than the controls show: focusing a control and pressing Enter changes
    // nothing.
    vtkNew<vtkVoxelGIPass> pass;
    pass->SetAmbientOcclusionFalloff(0.0004);
    pass->SetConeStepFactor(0.0504);
    vtkVoxelGISettingsWidget panel;
    panel.setPass(pass);
    for (const char* name : { "AmbientOcclusionFalloff", "ConeStepFactor" })
    {
      auto* spin = qobject_cast<QDoubleSpinBox*>(panel.control(name));
      spin->setFocus();
      QTest::keyClick(spin, Qt::Key_Return);
      spin->clearFocus();
    }
    QCOMPARE(pass->GetAmbientOcclusionFalloff(), 0.0004);
    QCOMPARE(pass->GetConeStepFactor(), 0.0504);
  }

  void resetRestoresDefaults()
  {
    vtkNew<vtkVoxelGIPass> pass;
    vtkVoxelGISettingsWidget panel;
    panel.setPass(pass);
    QSignalSpy restored(&panel, &vtkVoxelGISettingsWidget::defaultsRestored);
    panel.resetToDefaults();
    QCOMPARE(restored.count(), 0); // nothing changed: nothing to render again
    pass->SetBounces(7);
    pass->SetVoxelResolution(32);
    panel.resetToDefaults();
    QCOMPARE(restored.count(), 1); // the viewer renders again, once
    for (int i = 0; i < vtkVoxelGISettings::GetNumberOfSettings(); ++i)
    {
      QCOMPARE(vtkVoxelGISettings::GetValue(pass, vtkVoxelGISettings::GetName(i)),
        vtkVoxelGISettings::GetDefault(i));
    }
    QCOMPARE(qobject_cast<QSpinBox*>(panel.control("Bounces"))->value(), 3);
  }

  void viewerRenderAreaMatchesBaseline()
  {
    VoxelGIViewerWindow viewer;
    viewer.resize(900, 600);
    viewer.show();
    QVERIFY(QTest::qWaitForWindowExposed(&viewer));
    // A frame after a slow one shows a wait cursor and a message while it renders (read by an
    // observer that runs inside the render), none after; every frame counts as slow here.
    viewer.setBusyAfter(0.0);
    bool busy = false;
    auto* window = viewer.renderWindow();
    vtkNew<vtkCallbackCommand> probe;
    probe->SetClientData(&busy);
    probe->SetCallback([](vtkObject*, unsigned long, void* flag, void*) {
      *static_cast<bool*>(flag) = QApplication::overrideCursor() != nullptr;
    });
    const unsigned long tag = window->AddObserver(vtkCommand::StartEvent, probe, -1.0f); // after the viewer's
    QCOMPARE(viewer.pass()->GetVoxelResolution(), 128); // the defaults: Reset changes nothing
    window->Render();
    window->RemoveObserver(tag);
    QVERIFY2(busy, "no busy state during a slow frame");
    QVERIFY(QApplication::overrideCursor() == nullptr);
    QVERIFY(viewer.statusBar()->currentMessage().startsWith("Last frame: "));
    QVERIFY2(viewer.pass()->GetGIActive(), "GI did not run in the viewer");
    auto* timings = viewer.settings()->findChild<QLabel*>("Timings");
    QVERIFY(timings != nullptr);
    QVERIFY2(timings->text().contains("tick \"Time stages\""), qPrintable(timings->text()));
    viewer.pass()->TimeStagesOn();
    window->Render();
    QVERIFY2(timings->text().contains("Total"), qPrintable(timings->text()));
    viewer.pass()->TimeStagesOff();
    window->Render();

    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(viewer.renderWindow());
    grab->ReadFrontBufferOff();
    vtkNew<vtkTesting> testing;
    const QByteArray baseline = qgetenv("VOXELGI_BASELINE");
    const QByteArray temporary = qgetenv("VOXELGI_TEMP");
    for (const char* arg : { "-V", baseline.constData(), "-T", temporary.constData() })
    {
      testing->AddArgument(arg);
    }
    QCOMPARE(testing->RegressionTest(grab, 10.0), static_cast<int>(vtkTesting::PASSED));
  }
};

int main(int argc, char* argv[])
{
  QSurfaceFormat format = QVTKOpenGLNativeWidget::defaultFormat();
  format.setVersion(4, 5);
  QSurfaceFormat::setDefaultFormat(format);
  QApplication app(argc, argv);
  TestVoxelGIQt test;
  return QTest::qExec(&test, argc, argv);
}

#include "TestVoxelGIQt.moc"
