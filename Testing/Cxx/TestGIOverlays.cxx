// 2D overlays in viewports that do not start at the window's origin, as vedo with several
// renderers and two- or four-pane viewers draw them: two renderers side by side, each with a
// sphere on a floor, a text and a scalar bar, and a pass of its own with every GI term off
// (indirect light, AO, shadow and specular cones). The window equals plain VTK's within 3
// levels at 99.5 % of the pixels, in the frame that traces and in the unchanged frame after
// it (the overlays were drawn over the whole window, stretched, before). Then the image is
// compared with its baseline.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScalarBarActor.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"

#include <cstdlib>
#include <string>

namespace
{
constexpr int Width = 400;
constexpr int Height = 200;

vtkSmartPointer<vtkUnsignedCharArray> Pixels(vtkRenderWindow* window)
{
  auto pixels = vtkSmartPointer<vtkUnsignedCharArray>::New();
  window->GetPixelData(0, 0, Width - 1, Height - 1, 0, pixels);
  return pixels;
}

/// The share of the pixels that differ by more than 3 levels in a channel.
double Differing(vtkUnsignedCharArray* a, vtkUnsignedCharArray* b)
{
  vtkIdType differing = 0;
  for (vtkIdType p = 0; p < Width * Height; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (std::abs(static_cast<int>(a->GetValue(3 * p + c)) - b->GetValue(3 * p + c)) > 3)
      {
        ++differing;
        break;
      }
    }
  }
  return static_cast<double>(differing) / (Width * Height);
}
}

int TestGIOverlays(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(Width, Height);
  window->SetMultiSamples(0);
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-2.0, -0.5, -2.0);
  plane->SetPoint1(2.0, -0.5, -2.0);
  plane->SetPoint2(-2.0, -0.5, 2.0);
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkLookupTable> table;
  table->Build();
  vtkSmartPointer<vtkRenderer> renderers[2];
  vtkSmartPointer<vtkVoxelGIPass> passes[2];
  for (int i = 0; i < 2; ++i)
  {
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->SetViewport(0.5 * i, 0.0, 0.5 * i + 0.5, 1.0);
    window->AddRenderer(renderer);
    vtkNew<vtkActor> ball;
    ball->SetMapper(sphereMapper);
    renderer->AddActor(ball);
    vtkNew<vtkActor> floor;
    floor->SetMapper(planeMapper);
    renderer->AddActor(floor);
    vtkNew<vtkTextActor> text;
    text->SetInput(i == 0 ? "view 0" : "view 1");
    text->SetPosition(10, 10);
    text->GetTextProperty()->SetFontSize(20);
    renderer->AddActor2D(text);
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(table);
    bar->SetWidth(0.15);
    bar->SetHeight(0.6);
    renderer->AddActor2D(bar);
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPosition(1.0, 4.0, 3.0);
    renderer->AddLight(light);
    renderer->GetActiveCamera()->SetPosition(1.0, 2.0, 4.0);
    renderer->ResetCamera();
    passes[i] = vtkSmartPointer<vtkVoxelGIPass>::New();
    passes[i]->SetSoftwareProfileToOff();
    passes[i]->SetVoxelResolution(32);
    passes[i]->SetIndirectIntensity(0.0);
    passes[i]->SetAmbientOcclusionStrength(0.0);
    passes[i]->SetConeShadows(false);
    passes[i]->SetSpecularCone(false);
    renderers[i] = renderer;
  }
  window->Render();
  auto plain = Pixels(window);
  for (int i = 0; i < 2; ++i)
  {
    renderers[i]->SetPass(passes[i]);
  }
  const char* frames[2] = { "traced", "unchanged" };
  for (const char* frame : frames)
  {
    window->Render();
    VOXELGI_CHECK(passes[0]->GetGIActive() && passes[1]->GetGIActive(), "GI did not run");
    const double differing = Differing(plain, Pixels(window));
    std::cout << frame << " frame: " << 100.0 * differing << " % of the pixels differ from plain VTK"
              << std::endl;
    VOXELGI_CHECK(differing < 0.005, frame << ": the overlays are not where VTK draws them");
  }
  return voxelgi_test::ImageMatches(argc, argv, window);
}
