// What VTK draws looks as it does without the pass. Translucent, volume and overlay props:
// VTK draws them after the GI image with the renderer's own technique. Case "oit" (VTK's
// default order-independent translucency), "peeling" (depth peeling), "volume" (a GPU
// ray-cast volume), "overlay" (text): two intersecting translucent props over an opaque plane
// with a line on it; case "msaa": the same in an 8x multisampled window, whose edges and line
// keep VTK's anti-aliasing; case "points": translucent point clouds coloured by RGBA
// scalars, one drawn as spheres (as vedo's Points), in the 8x window; case "layer": the scene's
// renderer on a layer above another's red background, in a window of one sample (where the
// pass presents its G-buffer's image unless the renderer keeps colours below it). In a scene where GI has nothing to add (indirect light, AO,
// shadow and specular cones off), against plain VTK in the same window: at most 0.5 % of the
// pixels may differ by more than 3/255.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCubeSource.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLineSource.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPointSource.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

int TestGIVTKLook(int argc, char* argv[])
{
  const std::string which = argc > 1 ? argv[1] : "oit";
  vtkNew<vtkRenderer> renderer;
  using glm::dvec3;
  voxelgi_test::AddQuad(renderer, dvec3(-2, 0, -2), dvec3(-2, 0, 2), dvec3(2, 0, -2), 0.7, 0.7, 0.7);
  vtkNew<vtkLineSource> cut;
  cut->SetPoint1(-1.8, 0.0, 0.3);
  cut->SetPoint2(1.8, 0.0, 0.3);
  vtkActor* line = vtkVoxelGIScenes::AddSource(renderer, cut, 0.9, 0.1, 0.1);
  line->GetProperty()->SetLineWidth(3.0);
  vtkNew<vtkCubeSource> opaqueBlock; // something for GI to voxelize
  opaqueBlock->SetBounds(-1.8, -1.2, 0.0, 0.6, -1.8, -1.2);
  vtkVoxelGIScenes::AddSource(renderer, opaqueBlock, 0.3, 0.5, 0.8);
  if (which == "volume")
  {
    vtkNew<vtkImageData> density;
    density->SetDimensions(16, 16, 16);
    density->SetSpacing(0.1, 0.1, 0.1);
    density->SetOrigin(-0.75, 0.1, -0.75);
    density->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
    for (int k = 0; k < 16; ++k)
    {
      for (int j = 0; j < 16; ++j)
      {
        for (int i = 0; i < 16; ++i)
        {
          // a ball of density falling off from the middle
          const double r = std::sqrt((i - 7.5) * (i - 7.5) + (j - 7.5) * (j - 7.5) + (k - 7.5) * (k - 7.5));
          density->SetScalarComponentFromDouble(i, j, k, 0, std::max(0.0, 255.0 * (1.0 - r / 8.0)));
        }
      }
    }
    vtkNew<vtkGPUVolumeRayCastMapper> volumeMapper;
    volumeMapper->SetInputData(density);
    vtkNew<vtkColorTransferFunction> colors;
    colors->AddRGBPoint(0.0, 0.1, 0.2, 0.9);
    colors->AddRGBPoint(255.0, 0.9, 0.6, 0.1);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(255.0, 0.8);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(volumeMapper);
    volume->GetProperty()->SetColor(colors);
    volume->GetProperty()->SetScalarOpacity(opacity);
    volume->GetProperty()->SetScalarOpacityUnitDistance(0.05);
    renderer->AddVolume(volume);
  }
  else if (which == "points")
  {
    for (int cloud = 0; cloud < 2; ++cloud)
    {
      vtkNew<vtkPointSource> source;
      source->SetCenter(cloud ? 0.6 : -0.4, 0.7, 0.0);
      source->SetRadius(0.6);
      source->SetNumberOfPoints(400);
      source->Update();
      vtkPolyData* points = source->GetOutput();
      vtkNew<vtkUnsignedCharArray> rgba;
      rgba->SetNumberOfComponents(4);
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        rgba->InsertNextTuple4(255, (i * 37) % 256, 40, 60 + (i * 13) % 190);
      }
      points->GetPointData()->SetScalars(rgba);
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputData(points);
      mapper->SetColorModeToDirectScalars();
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->GetProperty()->SetPointSize(7.0);
      actor->GetProperty()->SetRenderPointsAsSpheres(cloud == 1);
      renderer->AddActor(actor);
    }
  }
  else
  {
    vtkNew<vtkCubeSource> box;
    box->SetBounds(-0.8, 0.6, 0.0, 1.0, -0.6, 0.8);
    vtkVoxelGIScenes::AddSource(renderer, box, 0.2, 0.8, 0.3)->GetProperty()->SetOpacity(0.4);
    vtkNew<vtkSphereSource> ball;
    ball->SetCenter(0.5, 0.6, 0.5);
    ball->SetRadius(0.6);
    ball->SetThetaResolution(32);
    ball->SetPhiResolution(32);
    vtkVoxelGIScenes::AddSource(renderer, ball, 0.9, 0.3, 0.2)->GetProperty()->SetOpacity(0.5);
  }
  vtkNew<vtkTextActor> text;
  if (which == "overlay")
  {
    text->SetInput("Overlay text 0.123");
    text->SetPosition(10, 10);
    text->GetTextProperty()->SetFontSize(18);
    renderer->AddActor2D(text);
  }
  renderer->SetUseDepthPeeling(which == "peeling");
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(1.0, 4.0, 3.0);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(light);
  renderer->GetActiveCamera()->SetPosition(1.5, 2.5, 4.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.4, 0.0);
  renderer->ResetCameraClippingRange();

  voxelgi_test::GIWindow view(renderer, 32, 200, which == "msaa" || which == "points" ? 8 : 0);
  vtkRenderWindow* window = view.Window;
  vtkNew<vtkRenderer> below;
  if (which == "layer")
  {
    below->SetBackground(0.6, 0.1, 0.1);
    window->SetNumberOfLayers(2);
    window->AddRenderer(below);
    renderer->SetLayer(1);
  }
  vtkVoxelGIPass* gi = view.GI;
  window->SetAlphaBitPlanes(1);
  view.RenderWithoutGI();
  vtkNew<vtkUnsignedCharArray> plain;
  window->GetRGBACharPixelData(0, 0, 199, 199, 0, plain);

  gi->SetIndirectIntensity(0.0);
  gi->SetAmbientOcclusionStrength(0.0);
  gi->SetConeShadows(false);
  gi->SetSpecularCone(false);
  window->Render();
  VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
  vtkNew<vtkUnsignedCharArray> withGI;
  window->GetRGBACharPixelData(0, 0, 199, 199, 0, withGI);

  vtkIdType differing = 0;
  for (vtkIdType i = 0; i < plain->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (std::abs(static_cast<int>(plain->GetValue(4 * i + c)) - withGI->GetValue(4 * i + c)) > 3)
      {
        ++differing;
        break;
      }
    }
  }
  const double fraction = static_cast<double>(differing) / plain->GetNumberOfTuples();
  std::cout << which << ": " << 100.0 * fraction << " % of the pixels differ from plain VTK"
            << std::endl;
  VOXELGI_CHECK(fraction < 0.005, which << ": the image differs from plain VTK's");
  return voxelgi_test::ImageMatches(argc, argv, window);
}
