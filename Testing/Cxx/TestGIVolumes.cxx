// Volumes in the voxels (VolumeVoxels): a homogeneous slab of known opacity between a light
// and a floor passes Beer-Lambert's share of the light, in the voxels' light and in the
// pixels' shadows; a volume alone is GI's scene, resampled only when it changes; what is left
// out is said.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
using glm::dvec3;
using voxelgi_test::StagesRan;
using voxelgi_test::Within;

/// A volume of constant scalar 1 filling the box [lo, hi] (points `spacing` apart), of
/// colour `rgb` and opacity `alpha` per `unit` of length.
vtkSmartPointer<vtkVolume> MakeSlab(const dvec3& lo, const dvec3& hi, double spacing,
  double alpha, double unit, const dvec3& rgb, int components = 1)
{
  vtkNew<vtkImageData> image;
  int dims[3];
  for (int i = 0; i < 3; ++i)
  {
    dims[i] = static_cast<int>(std::lround((hi[i] - lo[i]) / spacing)) + 1;
  }
  image->SetDimensions(dims);
  image->SetOrigin(lo.x, lo.y, lo.z);
  image->SetSpacing((hi.x - lo.x) / (dims[0] - 1), (hi.y - lo.y) / (dims[1] - 1),
    (hi.z - lo.z) / (dims[2] - 1));
  vtkNew<vtkFloatArray> scalars;
  scalars->SetName("density");
  scalars->SetNumberOfComponents(components);
  scalars->SetNumberOfTuples(image->GetNumberOfPoints());
  scalars->FillValue(1.f);
  image->GetPointData()->SetScalars(scalars);
  vtkSmartPointer<vtkVolume> volume = voxelgi_test::UniformVolume(image, alpha, unit, rgb);
  volume->GetProperty()->SetInterpolationTypeToLinear();
  return volume;
}

/// A sun straight above.
void AddSun(vtkRenderer* renderer)
{
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(2.0, 10.0, 2.0);
  sun->SetFocalPoint(2.0, 0.0, 2.0);
  renderer->AddLight(sun);
}

//------------------------------------------------------------------------------
// A black slab (it absorbs, scatters nothing) 0.5 thick over a white floor under a sun: the
// floor below keeps (1 - alpha)^(0.5 / unit) of the sun's light (Beer-Lambert), in the voxels
// and in the pixels.
int SlabTransmittance()
{
  bool ok = true;
  for (const double alpha : { 0.25, 0.5, 0.75 })
  {
    const double unit = 0.5, thickness = 0.5;
    const double expected = std::pow(1.0 - alpha, thickness / unit);
    voxelgi_test::GIWindow view(nullptr, 64, 100, 0);
    AddSun(view.Renderer);
    voxelgi_test::AddQuad(view.Renderer, dvec3(0.0, 0.0, 0.0), dvec3(0.0, 0.0, 4.0),
      dvec3(4.0, 0.0, 0.0), 0.8, 0.8, 0.8);
    view.Renderer->AddVolume(MakeSlab(
      dvec3(1.0, 1.0, 1.0), dvec3(3.0, 1.0 + thickness, 3.0), 0.05, alpha, unit, dvec3(0.0)));
    vtkCamera* camera = view.Renderer->GetActiveCamera();
    camera->SetPosition(2.0, 8.0, 2.0);
    camera->SetFocalPoint(2.0, 0.0, 2.0);
    camera->SetViewUp(0.0, 0.0, -1.0);
    camera->SetViewAngle(30.0);
    view.Renderer->ResetCameraClippingRange();
    voxelgi_test::Messages log(view.GI);
    view.Window->Render();
    VOXELGI_CHECK(view.GI->GetGIActive() && voxelgi_test::AllFinite(view.GI), "GI did not run");
    VOXELGI_CHECK(StagesRan(view.GI).find("Volumes") != std::string::npos,
      "the volume was not resampled: " << StagesRan(view.GI));
    VOXELGI_CHECK(!log.Has("vtkVolume"), "the volume was left out: " << log.Text);

    vtkNew<vtkImageData> radiance;
    VOXELGI_CHECK(view.GI->GetVoxelVolume(vtkVoxelGIPass::VOLUME_RADIANCE, radiance), "no voxels");
    const double lit = voxelgi_test::FloorRadiance(radiance, 0.4, 0.4);
    const double under = voxelgi_test::FloorRadiance(radiance, 2.0, 2.0);
    VOXELGI_CHECK(lit > 0.0, "the floor's voxels are dark");
    const double voxelRatio = under / lit;

    // The pixels: the composite (VTK draws the volume over it afterwards) under the slab's
    // middle against the lit floor near its edge, where the view looks straight down.
    vtkSmartPointer<vtkFloatArray> composite = voxelgi_test::Composite(view.GI);
    VOXELGI_CHECK(composite, "no composite");
    const double litPixels = voxelgi_test::MeanOver(composite, 100, 8, 8, 16, 16, 1);
    const double underPixels = voxelgi_test::MeanOver(composite, 100, 45, 45, 55, 55, 1);
    VOXELGI_CHECK(litPixels > 0.1, "the floor's pixels are dark: " << litPixels);
    const double pixelRatio = underPixels / litPixels;
    std::cout << "alpha " << alpha << ": Beer-Lambert " << expected << ", voxels " << voxelRatio
              << ", pixels " << pixelRatio << " (lit floor " << litPixels << ")" << std::endl;
    ok = Within("voxels' transmittance error, alpha " + std::to_string(alpha),
           std::abs(voxelRatio / expected - 1.0), 0.05, 0.05) && ok;
    ok = Within("pixels' transmittance error, alpha " + std::to_string(alpha),
           std::abs(pixelRatio / expected - 1.0), 0.05, 0.05) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

//------------------------------------------------------------------------------
// A thin volume (colour c) inside a closed box whose black walls emit radiance E: light E
// arrives at every sample from every side, so GI adds E times what the volume shows itself
// (VTK's unshaded volume shows c, as if lit by 1): the volume's pixels gain E x its own
// contribution, measured over a black background.
int VolumeLitByEmittingRoom()
{
  const double E = 0.5;
  voxelgi_test::GIWindow view(nullptr, 64, 100, 0);
  view.Renderer->AutomaticLightCreationOff();
  voxelgi_test::AddEmittingBox(view.Renderer, 4.0, E);
  vtkSmartPointer<vtkVolume> volume =
    MakeSlab(dvec3(1.5), dvec3(2.5), 0.05, 0.2, 1.0, dvec3(0.6, 0.5, 0.4));
  view.Renderer->AddVolume(volume);
  vtkCamera* camera = view.Renderer->GetActiveCamera();
  camera->SetPosition(2.0, 2.0, 3.9);
  camera->SetFocalPoint(2.0, 2.0, 2.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(40.0);
  view.Renderer->ResetCameraClippingRange();
  auto centre = [&view](bool gi) {
    gi ? view.Window->Render() : view.RenderWithoutGI();
    vtkNew<vtkFloatArray> pixels;
    view.Window->GetRGBAPixelData(0, 0, 99, 99, 0, pixels);
    return voxelgi_test::MeanOver(pixels, 100, 40, 40, 60, 60, 0);
  };
  const double lit = centre(true);
  VOXELGI_CHECK(view.GI->GetGIActive() && voxelgi_test::AllFinite(view.GI), "GI did not run");
  const double plain = centre(false);
  // The volume's own contribution: over black (the walls hidden).
  vtkPropCollection* props = view.Renderer->GetViewProps();
  props->InitTraversal();
  while (vtkProp* prop = props->GetNextProp())
  {
    prop->SetVisibility(prop == volume.GetPointer());
  }
  const double own = centre(false);
  const double added = (lit - plain) / own;
  std::cout << "volume in an emitting room (E " << E << "): plain " << plain << ", with GI " << lit
            << ", its own " << own << ": GI adds " << added << " x its own (E expected)"
            << std::endl;
  VOXELGI_CHECK(own > 0.05, "the volume shows nothing: " << own);
  return Within("volume lit by the room, error of what GI adds", std::abs(added / E - 1.0), 0.1,
           0.15)
    ? EXIT_SUCCESS
    : EXIT_FAILURE;
}

//------------------------------------------------------------------------------
// A volume is a scene of its own: GI runs, and it is resampled when it changes only.
int VolumeAloneResampledOnChange()
{
  voxelgi_test::GIWindow view(nullptr, 32, 80, 0);
  AddSun(view.Renderer);
  vtkSmartPointer<vtkVolume> volume =
    MakeSlab(dvec3(0.0), dvec3(2.0, 1.0, 2.0), 0.1, 0.5, 0.5, dvec3(0.9, 0.5, 0.2));
  view.Renderer->AddVolume(volume);
  view.Renderer->ResetCamera();
  voxelgi_test::Messages log(view.GI);
  auto ran = [&view](const char* stage) {
    return StagesRan(view.GI).find(stage) != std::string::npos;
  };
  view.Window->Render();
  VOXELGI_CHECK(view.GI->GetGIActive(), "GI did not run with a volume alone: " << log.Text);
  VOXELGI_CHECK(ran("Volumes") && ran("Resolve"), "first frame: " << StagesRan(view.GI));
  vtkNew<vtkImageData> albedo;
  VOXELGI_CHECK(view.GI->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, albedo), "no voxels");
  int partial = 0;
  vtkDataArray* values = albedo->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    const double a = values->GetComponent(i, 3);
    partial += (a > 0.0 && a < 255.0) ? 1 : 0;
  }
  std::cout << "voxels of partial occupancy: " << partial << std::endl;
  VOXELGI_CHECK(partial > 100, "the volume left no partial occupancy in the voxels");

  view.Window->Render();
  VOXELGI_CHECK(!ran("Volumes") && !ran("Resolve"), "unchanged frame: " << StagesRan(view.GI));
  view.Renderer->GetActiveCamera()->Azimuth(20.0);
  view.Window->Render();
  VOXELGI_CHECK(!ran("Volumes") && !ran("Resolve") && ran("ConeTrace"),
    "camera-only frame: " << StagesRan(view.GI));
  volume->GetProperty()->GetScalarOpacity()->AddPoint(1.0, 0.9);
  view.Window->Render();
  VOXELGI_CHECK(ran("Volumes") && ran("Resolve"), "transfer function changed: " << StagesRan(view.GI));
  volume->SetPosition(0.5, 0.0, 0.0);
  view.Window->Render();
  VOXELGI_CHECK(ran("Volumes"), "volume moved: " << StagesRan(view.GI));
  VOXELGI_CHECK(log.Count == 0, "messages: " << log.Text);
  return EXIT_SUCCESS;
}

//------------------------------------------------------------------------------
// What cannot be resampled is left to VTK with a notice that says why; a scene without a
// resampled volume resamples nothing.
int LeftOutVolumesSaid()
{
  voxelgi_test::GIWindow view(nullptr, 32, 80, 0);
  AddSun(view.Renderer);
  voxelgi_test::AddQuad(view.Renderer, dvec3(0.0, 0.0, 0.0), dvec3(0.0, 0.0, 4.0),
    dvec3(4.0, 0.0, 0.0), 0.8, 0.8, 0.8);
  vtkSmartPointer<vtkVolume> maximum =
    MakeSlab(dvec3(1.0), dvec3(2.0), 0.1, 0.5, 0.5, dvec3(1.0));
  vtkSmartVolumeMapper::SafeDownCast(maximum->GetMapper())->SetBlendModeToMaximumIntensity();
  view.Renderer->AddVolume(maximum);
  view.Renderer->AddVolume(
    MakeSlab(dvec3(2.5, 1.0, 1.0), dvec3(3.5, 2.0, 2.0), 0.1, 0.5, 0.5, dvec3(1.0), 2));
  view.Renderer->ResetCamera();
  voxelgi_test::Messages log(view.GI);
  view.Window->Render();
  VOXELGI_CHECK(view.GI->GetGIActive(), "GI did not run: " << log.Text);
  VOXELGI_CHECK(log.Has("a blend mode other than composite") &&
      log.Has("several scalar components"),
    "the notice does not say why: " << log.Text);
  VOXELGI_CHECK(StagesRan(view.GI).find("Volumes") == std::string::npos,
    "resampled a left-out volume: " << StagesRan(view.GI));
  return EXIT_SUCCESS;
}

voxelgi_test::Cases Cases()
{
  return { { "SlabTransmittance", SlabTransmittance },
    { "VolumeAloneResampledOnChange", VolumeAloneResampledOnChange },
    { "VolumeLitByEmittingRoom", VolumeLitByEmittingRoom },
    { "LeftOutVolumesSaid", LeftOutVolumesSaid } };
}
}

int TestGIVolumes(int argc, char* argv[])
{
  int result = EXIT_FAILURE;
  if (voxelgi_test::RunNamedCase(Cases(), argc, argv, result))
  {
    return result;
  }
  std::cerr << "FAILED: name a case" << std::endl;
  return EXIT_FAILURE;
}
