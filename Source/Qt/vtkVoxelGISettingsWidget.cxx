#include "vtkVoxelGISettingsWidget.h"

#include "vtkVoxelGIPass.h"
#include "vtkVoxelGISettings.h"

#include "vtkCallbackCommand.h"
#include "vtkRenderWindow.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace
{
const char* const GroupOrder[] = { "General", "Voxelization", "Lighting", "Cones", "Debug view",
  "Performance" };

/// Settings that take effect only while another setting has a value: their controls are
/// disabled otherwise, so that nobody edits a value the pass ignores.
struct Dependency
{
  const char* Setting;
  const char* On;
  int Value;
};
const Dependency Dependencies[] = {
  { "UpdateInterval", "UpdatePolicy", vtkVoxelGIPass::UPDATE_EVERY_N_FRAMES },
  { "ShadowMapResolution", "LightOcclusion", vtkVoxelGIPass::LIGHT_OCCLUSION_SHADOW_MAPS },
  { "SpecularIntensity", "SpecularCone", 1 },
  { "ShadowConeAperture", "ConeShadows", 1 },
};

/// "VoxelResolution" -> "Voxel resolution": a word starts at each capital that follows a
/// small letter or begins a capitalised word ("GBufferSamples" -> "G buffer samples").
QString Label(const QString& name)
{
  QString label = name.left(1);
  for (int i = 1; i < name.size(); ++i)
  {
    const bool beforeSmall = i + 1 < name.size() && name[i + 1].isLower();
    if (name[i].isUpper() && (name[i - 1].isLower() || beforeSmall))
    {
      label += ' ';
    }
    label += name[i].isUpper() && beforeSmall ? name[i].toLower() : name[i];
  }
  return label;
}

/// The setting's documentation, then its range (or values) and default.
QString ToolTip(int i)
{
  const QString type = QString::fromUtf8(vtkVoxelGISettings::GetType(i));
  const double lo = vtkVoxelGISettings::GetMinimum(i), hi = vtkVoxelGISettings::GetMaximum(i);
  const double d = vtkVoxelGISettings::GetDefault(i);
  QString range, byDefault;
  if (type == "bool")
  {
    byDefault = d != 0.0 ? QObject::tr("on") : QObject::tr("off");
  }
  else if (type == "enum")
  {
    const QStringList values =
      QString::fromUtf8(vtkVoxelGISettings::GetEnumerationValues(i)).split('|', Qt::SkipEmptyParts);
    range = QObject::tr("Values: %1.").arg(values.join(", "));
    byDefault = values.value(static_cast<int>(d));
  }
  else
  {
    range = QObject::tr("Range: %1 to %2%3.")
              .arg(lo)
              .arg(hi)
              .arg(vtkVoxelGISettings::GetPowerOfTwo(i) ? QObject::tr(", powers of two") : QString());
    byDefault = QString::number(d);
  }
  return QString::fromUtf8(vtkVoxelGISettings::GetDocumentation(i)) + "\n\n" + range +
    (range.isEmpty() ? "" : " ") + QObject::tr("Default: %1.").arg(byDefault);
}

/// Spin box of a setting that takes only powers of two: steps double or halve, and a typed
/// value is rounded as the pass rounds it, so the box never shows a value the pass would not use.
class PowerOfTwoSpinBox : public QSpinBox
{
public:
  PowerOfTwoSpinBox(int setting, QWidget* parent)
    : QSpinBox(parent)
    , Setting(setting)
  {
  }

  void stepBy(int steps) override
  {
    // bounded before the conversion to int: a page step is 2^10
    const double stepped = std::min(std::ldexp(this->value(), steps), 1.0 * this->maximum());
    this->setValue(this->Nearest(static_cast<int>(stepped)));
    this->selectAll();
  }

protected:
  QValidator::State validate(QString& input, int& pos) const override
  {
    const QValidator::State state = QSpinBox::validate(input, pos);
    // Other numbers are not final: when editing ends, the spin box has fixup() round them.
    if (state == QValidator::Acceptable)
    {
      const int typed = this->valueFromText(input);
      return this->Nearest(typed) == typed ? state : QValidator::Intermediate;
    }
    return state;
  }

  void fixup(QString& input) const override
  {
    bool number = false;
    const int typed = this->locale().toInt(input, &number);
    if (number)
    {
      input = this->textFromValue(this->Nearest(typed));
    }
  }

private:
  int Nearest(int value) const
  {
    return vtkVoxelGISettings::NearestPowerOfTwo(this->Setting, value);
  }

  const int Setting;
};
}

QWidget* vtkVoxelGISettingsWidget::createControl(int i, const QString& name)
{
  const QString type = QString::fromUtf8(vtkVoxelGISettings::GetType(i));
  const double lo = vtkVoxelGISettings::GetMinimum(i);
  const double hi = vtkVoxelGISettings::GetMaximum(i);
  if (type == "bool")
  {
    auto* check = new QCheckBox(this);
    connect(check, &QCheckBox::toggled, this, [this, name](bool on) { this->apply(name, on); });
    return check;
  }
  if (type == "enum")
  {
    auto* combo = new QComboBox(this);
    combo->addItems(QString::fromUtf8(vtkVoxelGISettings::GetEnumerationValues(i))
                      .split('|', Qt::SkipEmptyParts));
    connect(combo, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
      [this, name](int index) { this->apply(name, index); });
    return combo;
  }
  if (type == "int")
  {
    auto* spin = vtkVoxelGISettings::GetPowerOfTwo(i) ? new PowerOfTwoSpinBox(i, this)
                                                      : new QSpinBox(this);
    spin->setRange(static_cast<int>(lo), static_cast<int>(hi));
    connect(spin, QOverload<int>::of(&QSpinBox::valueChanged), this,
      [this, name](int value) { this->apply(name, value); });
    return spin;
  }
  auto* spin = new QDoubleSpinBox(this);
  spin->setDecimals(3);
  spin->setRange(lo, hi);
  spin->setSingleStep((hi - lo) / 100.0);
  connect(spin, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
    [this, name, spin](double value) { this->applyShown(name, value, spin->decimals()); });
  return spin;
}

vtkVoxelGISettingsWidget::vtkVoxelGISettingsWidget(QWidget* parent)
  : QWidget(parent)
{
  auto* layout = new QVBoxLayout(this);
  // The read-out first: it is what changes at each render, visible without scrolling.
  this->Timings = new QLabel(this);
  this->Timings->setObjectName("Timings");
  this->Timings->setTextFormat(Qt::PlainText);
  this->Timings->setWordWrap(true); // the panel keeps the width its controls need
  layout->addWidget(this->Timings);
  QMap<QString, QFormLayout*> groups;
  for (const char* group : GroupOrder)
  {
    auto* box = new QGroupBox(QString::fromUtf8(group), this);
    auto* form = new QFormLayout(box);
    groups[group] = form;
    layout->addWidget(box);
  }

  for (int i = 0; i < vtkVoxelGISettings::GetNumberOfSettings(); ++i)
  {
    const QString name = QString::fromUtf8(vtkVoxelGISettings::GetName(i));
    QWidget* control = this->createControl(i, name);
    control->setObjectName(name);
    control->setToolTip(ToolTip(i));
    auto* label = new QLabel(Label(name), this);
    label->setToolTip(control->toolTip());
    label->setBuddy(control);
    QFormLayout* form = groups.value(QString::fromUtf8(vtkVoxelGISettings::GetGroup(i)), nullptr);
    (form ? form : groups["General"])->addRow(label, control);
    this->Names << name;
    this->Controls[name] = control;
  }

  auto* reset = new QPushButton(tr("Reset to defaults"), this);
  connect(reset, &QPushButton::clicked, this, &vtkVoxelGISettingsWidget::resetToDefaults);
  layout->addWidget(reset);
  layout->addStretch();

  this->PassObserver = vtkCallbackCommand::New();
  this->PassObserver->SetClientData(this);
  this->PassObserver->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
    static_cast<vtkVoxelGISettingsWidget*>(self)->updateControls();
  });
  this->WindowObserver = vtkCallbackCommand::New();
  this->WindowObserver->SetClientData(this);
  this->WindowObserver->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
    static_cast<vtkVoxelGISettingsWidget*>(self)->updateTimings();
  });
  this->setEnabled(false);
}

vtkVoxelGISettingsWidget::~vtkVoxelGISettingsWidget()
{
  this->setPass(nullptr);
  this->setRenderWindow(nullptr);
  this->PassObserver->Delete();
  this->WindowObserver->Delete();
}

void vtkVoxelGISettingsWidget::setPass(vtkVoxelGIPass* pass)
{
  if (this->Pass)
  {
    this->Pass->RemoveObserver(this->PassTag);
    this->Pass->UnRegister(nullptr);
  }
  this->Pass = pass;
  if (pass)
  {
    pass->Register(nullptr);
    this->PassTag = pass->AddObserver(vtkCommand::ModifiedEvent, this->PassObserver);
  }
  this->setEnabled(pass != nullptr);
  this->updateControls();
}

void vtkVoxelGISettingsWidget::setRenderWindow(vtkRenderWindow* window)
{
  if (this->Window)
  {
    this->Window->RemoveObserver(this->WindowTag);
  }
  this->Window = window;
  if (window)
  {
    this->WindowTag = window->AddObserver(vtkCommand::EndEvent, this->WindowObserver);
  }
}

void vtkVoxelGISettingsWidget::apply(const QString& name, double value)
{
  if (this->Updating || !this->Pass)
  {
    return;
  }
  vtkVoxelGISettings::SetValue(this->Pass, name.toUtf8().constData(), value);
  Q_EMIT this->settingChanged(name, vtkVoxelGISettings::GetValue(this->Pass, name.toUtf8().constData()));
}

void vtkVoxelGISettingsWidget::applyShown(const QString& name, double value, int decimals)
{
  if (this->Pass &&
    std::abs(vtkVoxelGISettings::GetValue(this->Pass, name.toUtf8().constData()) - value) <
      0.5 * std::pow(10.0, -decimals))
  {
    return;
  }
  this->apply(name, value);
}

void vtkVoxelGISettingsWidget::updateControls()
{
  if (!this->Pass || this->Updating)
  {
    return;
  }
  // Guard against feedback: setting a control fires its signal, which would set the pass.
  this->Updating = true;
  for (const QString& name : this->Names)
  {
    const double value = vtkVoxelGISettings::GetValue(this->Pass, name.toUtf8().constData());
    QWidget* control = this->Controls[name];
    if (auto* check = qobject_cast<QCheckBox*>(control))
    {
      check->setChecked(value != 0.0);
    }
    else if (auto* combo = qobject_cast<QComboBox*>(control))
    {
      combo->setCurrentIndex(static_cast<int>(std::lround(value)));
    }
    else if (auto* spin = qobject_cast<QSpinBox*>(control))
    {
      spin->setValue(static_cast<int>(std::lround(value)));
    }
    else if (auto* dspin = qobject_cast<QDoubleSpinBox*>(control))
    {
      dspin->setValue(value);
    }
  }
  for (const Dependency& d : Dependencies)
  {
    if (QWidget* control = this->Controls.value(d.Setting, nullptr))
    {
      control->setEnabled(std::lround(vtkVoxelGISettings::GetValue(this->Pass, d.On)) == d.Value);
    }
  }
  this->Updating = false;
}

void vtkVoxelGISettingsWidget::resetToDefaults()
{
  if (!this->Pass)
  {
    return;
  }
  const vtkMTimeType before = this->Pass->GetMTime();
  for (int i = 0; i < vtkVoxelGISettings::GetNumberOfSettings(); ++i)
  {
    vtkVoxelGISettings::SetValue(this->Pass, vtkVoxelGISettings::GetName(i), vtkVoxelGISettings::GetDefault(i));
  }
  this->updateControls();
  if (this->Pass->GetMTime() != before)
  {
    Q_EMIT this->defaultsRestored(); // one render for all of them, not one per setting
  }
}

void vtkVoxelGISettingsWidget::updateTimings()
{
  if (!this->Pass)
  {
    return;
  }
  if (!this->Pass->GetGIActive())
  {
    this->Timings->setText(tr("Last frame: GI not active"));
    return;
  }
  // Without timer queries the stages are listed (ran or not) but not timed.
  const bool timed = this->Pass->GetTimeStages() != 0;
  QString text = timed ? tr("Last frame:\n") : tr("Last frame (tick \"Time stages\" for times):\n");
  double total = 0.0;
  for (int stage = 0; stage < vtkVoxelGIPass::NUMBER_OF_STAGES; ++stage)
  {
    if (this->Pass->GetStageRan(stage))
    {
      const QString name = QString::fromUtf8(vtkVoxelGIPass::GetStageName(stage));
      total += this->Pass->GetStageTime(stage);
      text += timed ? QString("  %1  %2 ms\n").arg(name, -16).arg(this->Pass->GetStageTime(stage), 0, 'f', 2)
                    : QString("  %1\n").arg(name);
    }
  }
  if (timed)
  {
    text += QString("  %1  %2 ms").arg(tr("Total"), -16).arg(total, 0, 'f', 2);
  }
  this->Timings->setText(text.trimmed());
}
