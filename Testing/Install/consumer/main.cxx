// Sets the pass on a renderer and shows its settings panel once (Qt's offscreen platform is
// enough): prints the pass's class and the number of settings the panel shows.
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGISettingsWidget.h"

#include "vtkNew.h"
#include "vtkRenderer.h"

#include <QApplication>

#include <iostream>

int main(int argc, char* argv[])
{
  QApplication app(argc, argv);
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkVoxelGIPass> gi;
  renderer->SetPass(gi);
  vtkVoxelGISettingsWidget panel;
  panel.setPass(gi);
  std::cout << gi->GetClassName() << " " << panel.findChildren<QWidget*>().size() << std::endl;
  return 0;
}
