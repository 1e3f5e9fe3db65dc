// Renders the built-in Cornell box with voxel GI on and writes the images:
//   VoxelGIDemo [output-prefix] [--egl]  ->  <prefix>.png (GI), <prefix>-plain.png (VTK
//                                            without GI) and <prefix>-voxels.png (voxels)
// --egl renders headless through EGL (GPU machines without an X server).
#include "vtkVoxelGIEGLRenderWindow.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkWindowToImageFilter.h"

#include <iostream>
#include <string>

namespace
{
void WritePNG(vtkRenderWindow* window, const std::string& path)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(path.c_str());
  writer->Write();
  std::cout << "wrote " << path << std::endl;
}
}

int main(int argc, char* argv[])
{
  std::string prefix = "voxelgi-demo";
  bool egl = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--egl")
    {
      egl = true;
    }
    else
    {
      prefix = arg;
    }
  }

  vtkNew<vtkRenderer> renderer;
  vtkVoxelGIScenes::AddCornellBox(renderer);
  vtkSmartPointer<vtkRenderWindow> window = egl
    ? vtkSmartPointer<vtkRenderWindow>(vtkSmartPointer<vtkVoxelGIEGLRenderWindow>::New())
    : vtkSmartPointer<vtkRenderWindow>::New();
  window->SetSize(640, 640);
  window->SetOffScreenRendering(true);
  window->AddRenderer(renderer);

  vtkNew<vtkVoxelGIPass> gi;
  gi->SetVoxelResolution(128);
  gi->SetSoftwareProfileToOff(); // a still image: the full settings, also on a CPU renderer
  gi->TimeStagesOn();
  renderer->SetPass(gi);

  window->Render();
  if (!gi->GetGIActive())
  {
    std::cerr << "Voxel GI could not run on this OpenGL context." << std::endl;
    return EXIT_FAILURE;
  }
  WritePNG(window, prefix + ".png");
  gi->Print(std::cout);

  gi->SetDebugViewToVoxelAlbedo();
  window->Render();
  WritePNG(window, prefix + "-voxels.png");

  gi->SetDebugViewToNone();
  gi->EnabledOff();
  window->Render();
  WritePNG(window, prefix + "-plain.png");
  return EXIT_SUCCESS;
}
