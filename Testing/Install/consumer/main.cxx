// Runs README.md's C++ snippets verbatim (readme_snippets.h, which test_install.sh writes
// from the README) on a small lit scene in a window, then shows the settings panel once
// (Qt's offscreen platform is enough): prints the pass's class, the number of settings the
// panel shows, and whether the snippets' pass traced.
#include "readme_snippets.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <QApplication>
#include <QWidget>

#include <iostream>

namespace
{
/// An actor showing the box [lo, hi] (six quads, from the modules the pass links).
vtkSmartPointer<vtkActor> MakeBox(const double lo[3], const double hi[3])
{
  vtkNew<vtkPoints> points;
  for (int corner = 0; corner < 8; ++corner)
  {
    points->InsertNextPoint(corner & 1 ? hi[0] : lo[0], corner & 2 ? hi[1] : lo[1],
      corner & 4 ? hi[2] : lo[2]);
  }
  const vtkIdType faces[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 },
    { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  vtkNew<vtkCellArray> quads;
  for (const auto& face : faces)
  {
    quads->InsertNextCell(4, face);
  }
  vtkNew<vtkPolyData> box;
  box->SetPoints(points);
  box->SetPolys(quads);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(box);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}
}

int main(int argc, char* argv[])
{
  QApplication app(argc, argv);
  QWidget parent;
  const double blockLo[3] = { -0.5, -1.0, -0.5 }, blockHi[3] = { 0.5, 0.0, 0.5 };
  const double floorLo[3] = { -2.0, -1.1, -2.0 }, floorHi[3] = { 2.0, -1.0, 2.0 };
  const double lampLo[3] = { -0.5, 1.5, -0.5 }, lampHi[3] = { 0.5, 1.6, 0.5 };
  vtkSmartPointer<vtkActor> movingActor = MakeBox(blockLo, blockHi);
  vtkSmartPointer<vtkActor> lampActor = MakeBox(lampLo, lampHi);
  vtkSmartPointer<vtkActor> floorActor = MakeBox(floorLo, floorHi);
  vtkNew<vtkRenderer> renderer;
  for (vtkActor* actor : { movingActor.GetPointer(), lampActor.GetPointer(), floorActor.GetPointer() })
  {
    renderer->AddActor(actor);
  }
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(1.0, 4.0, 2.0);
  renderer->AddLight(light);
  vtkNew<vtkRenderWindow> renderWindow;
  renderWindow->SetOffScreenRendering(true);
  renderWindow->SetSize(120, 120);
  renderWindow->AddRenderer(renderer);

  vtkVoxelGIPass* gi = RunReadmeSnippets(&parent, renderer, lampActor, movingActor, renderWindow);
  std::cout << gi->GetClassName() << " " << parent.findChildren<QWidget*>().size()
            << " snippets traced " << gi->GetGIActive() << std::endl;
  gi->Delete();
  return 0;
}
