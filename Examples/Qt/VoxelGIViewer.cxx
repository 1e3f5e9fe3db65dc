// The VoxelGI Qt example viewer.
//   VoxelGIViewer                        interactive
//   VoxelGIViewer --screenshot out.png   render once, save the window, quit
#include "VoxelGIViewerWindow.h"

#include "QVTKOpenGLNativeWidget.h"

#include <QApplication>
#include <QScreen>
#include <QSurfaceFormat>
#include <QTimer>

int main(int argc, char* argv[])
{
  // GI needs OpenGL 4.3; QVTKOpenGLNativeWidget asks for 3.2 core by default.
  QSurfaceFormat format = QVTKOpenGLNativeWidget::defaultFormat();
  format.setVersion(4, 5);
  QSurfaceFormat::setDefaultFormat(format);
  QApplication app(argc, argv);

  VoxelGIViewerWindow window;
  window.resize(1100, 700);
  window.show();
  const QStringList args = app.arguments();
  const int at = args.indexOf("--screenshot");
  if (at >= 0 && at + 1 < args.size())
  {
    const QString path = args[at + 1];
    QTimer::singleShot(500, [&window, path]() {
      window.grab().save(path);
      QApplication::quit();
    });
  }
  return app.exec();
}
