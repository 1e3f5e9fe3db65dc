#include "VoxelGIViewerWindow.h"

#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"
#include "vtkVoxelGISettingsWidget.h"

#include "QVTKOpenGLNativeWidget.h"
#include "vtkActor.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkContourFilter.h"
#include "vtkElevationFilter.h"
#include "vtkGenericOpenGLRenderWindow.h"
#include "vtkGlyph3D.h"
#include "vtkLight.h"
#include "vtkOBJReader.h"
#include "vtkPlaneSource.h"
#include "vtkPointSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkXMLPolyDataReader.h"

#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QMenuBar>
#include <QScrollArea>
#include <QStatusBar>
#include <QToolBar>

namespace
{
// A floor and two walls around the bounds, and a light above: a room for a dataset.
void AddRoom(vtkRenderer* renderer, const double b[6])
{
  const double dx = b[1] - b[0], dy = b[3] - b[2], dz = b[5] - b[4];
  const double m = 0.4 * std::max({ dx, dy, dz, 1e-6 });
  const double x0 = b[0] - m, x1 = b[1] + m, y0 = b[2] - 0.05 * m, y1 = b[3] + m, z0 = b[4] - m,
               z1 = b[5] + m;
  auto quad = [renderer](double ox, double oy, double oz, double ax, double ay, double az,
                double bx, double by, double bz) {
    vtkNew<vtkPlaneSource> plane;
    plane->SetOrigin(ox, oy, oz);
    plane->SetPoint1(ax, ay, az);
    plane->SetPoint2(bx, by, bz);
    vtkVoxelGIScenes::AddSource(renderer, plane, 0.85, 0.85, 0.8);
  };
  quad(x0, y0, z0, x0, y0, z1, x1, y0, z0); // floor
  quad(x0, y0, z0, x1, y0, z0, x0, y1, z0); // back wall
  quad(x0, y0, z0, x0, y1, z0, x0, y0, z1); // left wall
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetConeAngle(90.0);
  light->SetPosition(0.5 * (x0 + x1) + 0.3 * dx, y1, 0.5 * (z0 + z1) + 0.6 * dz + m);
  light->SetFocalPoint(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]));
  renderer->AddLight(light);
}
}

VoxelGIViewerWindow::VoxelGIViewerWindow(QWidget* parent)
  : QMainWindow(parent)
{
  this->setWindowTitle(tr("VoxelGI viewer"));
  this->View = new QVTKOpenGLNativeWidget(this);
  this->View->setRenderWindow(this->Window);
  this->Window->AddRenderer(this->Renderer);
  this->Renderer->SetPass(this->Pass);
  this->Window->AddObserver(vtkCommand::StartEvent, this, &VoxelGIViewerWindow::renderStarted);
  this->Window->AddObserver(vtkCommand::EndEvent, this, &VoxelGIViewerWindow::renderEnded);
  this->setCentralWidget(this->View);

  this->Settings = new vtkVoxelGISettingsWidget(this);
  this->Settings->setPass(this->Pass);
  this->Settings->setRenderWindow(this->Window);
  const auto render = [this]() { this->View->renderWindow()->Render(); };
  connect(this->Settings, &vtkVoxelGISettingsWidget::settingChanged, this, render);
  connect(this->Settings, &vtkVoxelGISettingsWidget::defaultsRestored, this, render);
  auto* scroll = new QScrollArea(this);
  scroll->setWidget(this->Settings);
  scroll->setWidgetResizable(true);
  auto* dock = new QDockWidget(tr("Voxel GI"), this);
  dock->setWidget(scroll);
  this->addDockWidget(Qt::RightDockWidgetArea, dock);

  auto* toolbar = this->addToolBar(tr("Scene"));
  this->SceneChooser = new QComboBox(toolbar);
  this->SceneChooser->addItems({ tr("Cornell box"), tr("Wavelet isosurface"), tr("Glyph field") });
  toolbar->addWidget(this->SceneChooser);
  connect(this->SceneChooser, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
    &VoxelGIViewerWindow::showScene);
  QMenu* file = this->menuBar()->addMenu(tr("&File"));
  file->addAction(tr("&Open .vtp or .obj..."), this, [this]() {
    const QString path = QFileDialog::getOpenFileName(
      this, tr("Open"), QString(), tr("Surfaces (*.vtp *.obj)"));
    if (!path.isEmpty())
    {
      this->openFile(path);
    }
  });
  file->addAction(tr("&Quit"), this, &QWidget::close);
  this->showScene(0);
}

VoxelGIViewerWindow::~VoxelGIViewerWindow() = default;

void VoxelGIViewerWindow::renderStarted()
{
  this->RenderClock.start();
  // A slow frame (a software renderer, a voxel rebuild at a high resolution) blocks the event
  // loop: say so before it starts. Fast frames (interaction on a GPU) show nothing.
  if (this->LastFrameSeconds >= this->BusyAfter)
  {
    QApplication::setOverrideCursor(Qt::WaitCursor);
    this->Busy = true;
    this->statusBar()->showMessage(tr("Rendering..."));
    this->statusBar()->repaint();
  }
}

void VoxelGIViewerWindow::renderEnded()
{
  this->LastFrameSeconds = 1e-3 * static_cast<double>(this->RenderClock.elapsed());
  if (this->Busy)
  {
    QApplication::restoreOverrideCursor();
    this->Busy = false;
  }
  this->statusBar()->showMessage(tr("Last frame: %1 s").arg(this->LastFrameSeconds, 0, 'f', 2));
}

void VoxelGIViewerWindow::resetRenderer()
{
  this->Renderer->RemoveAllViewProps();
  this->Renderer->RemoveAllLights();
  this->Renderer->GetActiveCamera()->SetPosition(0, 0, 1);
  this->Renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  this->Renderer->GetActiveCamera()->SetViewUp(0, 1, 0);
}

void VoxelGIViewerWindow::showScene(int scene)
{
  this->resetRenderer();
  if (scene == 1)
  {
    vtkNew<vtkRTAnalyticSource> wavelet;
    wavelet->SetWholeExtent(-10, 10, -10, 10, -10, 10);
    vtkNew<vtkContourFilter> contour;
    contour->SetInputConnection(wavelet->GetOutputPort());
    contour->SetValue(0, 190.0);
    vtkNew<vtkElevationFilter> elevation;
    elevation->SetInputConnection(contour->GetOutputPort());
    elevation->SetLowPoint(0, -10, 0);
    elevation->SetHighPoint(0, 10, 0);
    elevation->Update();
    vtkVoxelGIScenes::AddSource(this->Renderer, elevation, 1, 1, 1);
    AddRoom(this->Renderer, elevation->GetOutput()->GetBounds());
  }
  else if (scene == 2)
  {
    vtkNew<vtkPointSource> points;
    points->SetNumberOfPoints(60);
    points->SetRadius(4.0);
    points->SetCenter(0, 4, 0);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetRadius(0.6);
    vtkNew<vtkGlyph3D> glyphs;
    glyphs->SetInputConnection(points->GetOutputPort());
    glyphs->SetSourceConnection(sphere->GetOutputPort());
    glyphs->Update();
    vtkVoxelGIScenes::AddSource(this->Renderer, glyphs, 0.9, 0.5, 0.2);
    AddRoom(this->Renderer, glyphs->GetOutput()->GetBounds());
  }
  else
  {
    vtkVoxelGIScenes::AddCornellBox(this->Renderer);
  }
  if (scene != 0)
  {
    this->Renderer->GetActiveCamera()->Azimuth(30);
    this->Renderer->GetActiveCamera()->Elevation(15);
    this->Renderer->ResetCamera();
  }
  this->Window->Render();
}

bool VoxelGIViewerWindow::openFile(const QString& path)
{
  vtkSmartPointer<vtkAlgorithm> reader;
  if (path.endsWith(".obj", Qt::CaseInsensitive))
  {
    auto obj = vtkSmartPointer<vtkOBJReader>::New();
    obj->SetFileName(path.toUtf8().constData());
    reader = obj;
  }
  else
  {
    auto vtp = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    vtp->SetFileName(path.toUtf8().constData());
    reader = vtp;
  }
  reader->Update();
  vtkDataSet* data = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (!data || data->GetNumberOfPoints() == 0)
  {
    return false;
  }
  this->resetRenderer();
  vtkVoxelGIScenes::AddSource(this->Renderer, reader, 0.8, 0.8, 0.85);
  AddRoom(this->Renderer, data->GetBounds());
  this->Renderer->GetActiveCamera()->Azimuth(30);
  this->Renderer->GetActiveCamera()->Elevation(15);
  this->Renderer->ResetCamera();
  this->Window->Render();
  return true;
}
