// Translucent surfaces in GI (ShadowTransmittance): a plane of opacity a and colour c between
// a sun and a floor passes (1 - a) mix(1, c, a) of the light (tinted by its colour as much as
// it is opaque), in the voxels' light and in the pixels'
// shadows, whether the actor's property or its scalars through a lookup table colour it; a
// translucent surface behind the receiver takes nothing away; VTK still draws it, with the
// indirect light it receives (TranslucentLighting). In the voxels a translucent surface stops
// the share of light its opacity says (partial occupancy), and a sunlit plane, translucent or
// opaque, does not light the floor under it through itself.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLookupTable.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
using glm::dvec3;
using voxelgi_test::Within;

/// A floor [0, 4]^2 at y = 0 under a sun straight above, seen from above (100 x 100 pixels).
struct SunOverFloor
{
  voxelgi_test::GIWindow View{ nullptr, 64, 100, 0 };
  SunOverFloor()
  {
    vtkRenderer* renderer = this->View.Renderer;
    renderer->AutomaticLightCreationOff();
    vtkNew<vtkLight> sun;
    sun->SetLightTypeToSceneLight();
    sun->SetPositional(false);
    sun->SetPosition(2.0, 10.0, 2.0);
    sun->SetFocalPoint(2.0, 0.0, 2.0);
    renderer->AddLight(sun);
    voxelgi_test::AddQuad(
      renderer, dvec3(0.0, 0.0, 0.0), dvec3(0.0, 0.0, 4.0), dvec3(4.0, 0.0, 0.0), 0.8, 0.8, 0.8);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(2.0, 8.0, 2.0);
    camera->SetFocalPoint(2.0, 0.0, 2.0);
    camera->SetViewUp(0.0, 0.0, -1.0);
    camera->SetViewAngle(30.0);
  }
  /// The sun's light alone: no bounces, no indirect light in the pixels (what passes a
  /// plane is then its transmittance alone).
  void DirectOnly()
  {
    this->View.GI->SetBounces(0);
    this->View.GI->SetIndirectIntensity(0.0);
  }
  /// A translucent plane over [1, 3]^2 at height y, of colour rgb and opacity alpha.
  vtkActor* AddPlane(double y, const dvec3& rgb, double alpha)
  {
    vtkActor* plane = voxelgi_test::AddQuad(this->View.Renderer, dvec3(1.0, y, 1.0),
      dvec3(1.0, y, 3.0), dvec3(3.0, y, 1.0), rgb.x, rgb.y, rgb.z);
    plane->GetProperty()->SetOpacity(alpha);
    return plane;
  }
  /// Render (EXIT_SUCCESS, else a failure is printed); the floor's radiance per channel under the plane's middle against its open part,
  /// in the voxels (summed over the floor's voxel layers) and in the composite's pixels.
  int Measure(std::array<double, 3>& voxels, std::array<double, 3>& pixels, double& lit)
  {
    this->View.Renderer->ResetCameraClippingRange();
    voxelgi_test::Messages log(this->View.GI);
    this->View.Window->Render();
    VOXELGI_CHECK(this->View.GI->GetGIActive() && voxelgi_test::AllFinite(this->View.GI),
      "GI did not run");
    VOXELGI_CHECK(!log.Has("translucent"), "a translucent actor was left out: " << log.Text);
    vtkNew<vtkImageData> radiance;
    VOXELGI_CHECK(
      this->View.GI->GetVoxelVolume(vtkVoxelGIPass::VOLUME_RADIANCE, radiance), "no voxels");
    vtkSmartPointer<vtkFloatArray> composite = voxelgi_test::Composite(this->View.GI);
    VOXELGI_CHECK(composite, "no composite");
    lit = voxelgi_test::MeanOver(composite, 100, 8, 8, 16, 16, 1);
    for (int c = 0; c < 3; ++c)
    {
      voxels[c] = voxelgi_test::FloorRadiance(radiance, 2.0, 2.0, c) /
        voxelgi_test::FloorRadiance(radiance, 0.4, 0.4, c);
      pixels[c] = voxelgi_test::MeanOver(composite, 100, 45, 45, 55, 55, c) /
        voxelgi_test::MeanOver(composite, 100, 8, 8, 16, 16, c);
    }
    return EXIT_SUCCESS;
  }
};

/// Whether each channel of the measured ratios is within 0.05 of (1 - alpha) mix(1, rgb, alpha).
bool Transmits(const std::string& what, const dvec3& rgb, double alpha,
  const std::array<double, 3>& voxels, const std::array<double, 3>& pixels)
{
  bool ok = true;
  for (int c = 0; c < 3; ++c)
  {
    const double expected = (1.0 - alpha) * (1.0 - alpha + alpha * rgb[c]);
    std::cout << what << ", channel " << c << ": (1 - a) mix(1, c, a) " << expected << ", voxels "
              << voxels[c] << ", pixels " << pixels[c] << std::endl;
    const std::string channel = what + ", channel " + std::to_string(c);
    ok = Within(channel + ": voxels' transmittance error", std::abs(voxels[c] - expected), 0.05,
           0.05) && ok;
    ok = Within(channel + ": pixels' transmittance error", std::abs(pixels[c] - expected), 0.05,
           0.05) && ok;
  }
  return ok;
}

//------------------------------------------------------------------------------
// A plane coloured by its property: (1 - a) mix(1, c, a) of the sun passes, for three
// opacities.
int PlaneTransmittance()
{
  bool ok = true;
  const dvec3 rgb(1.0, 0.6, 0.3);
  for (const double alpha : { 0.25, 0.5, 0.75 })
  {
    SunOverFloor scene;
    scene.DirectOnly();
    scene.AddPlane(1.0, rgb, alpha);
    std::array<double, 3> voxels{}, pixels{};
    double lit = 0.0;
    VOXELGI_CHECK(scene.Measure(voxels, pixels, lit) == EXIT_SUCCESS, "not measured");
    VOXELGI_CHECK(lit > 0.1, "the floor's pixels are dark: " << lit);
    ok = Transmits("opacity " + std::to_string(alpha), rgb, alpha, voxels, pixels) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

// A plane coloured by point scalars through a lookup table whose alpha makes it translucent
// (the actor's opacity is 1); where the table hides it (alpha 0), all the light passes.
int ScalarColorsTransmittance()
{
  const dvec3 rgb(0.2, 0.8, 0.4);
  bool ok = true;
  for (const double alpha : { 0.6, 0.0 })
  {
    SunOverFloor scene;
    scene.DirectOnly();
    vtkActor* plane = scene.AddPlane(1.0, dvec3(1.0), 1.0);
    vtkMapper* mapper = plane->GetMapper();
    mapper->Update();
    vtkNew<vtkPolyData> data;
    data->DeepCopy(mapper->GetInputDataObject(0, 0));
    mapper->SetInputDataObject(data);
    vtkNew<vtkFloatArray> scalars;
    scalars->SetNumberOfTuples(data->GetNumberOfPoints());
    scalars->FillValue(0.5f);
    data->GetPointData()->SetScalars(scalars);
    vtkNew<vtkLookupTable> table;
    table->SetNumberOfTableValues(1);
    table->SetTableValue(0, rgb.x, rgb.y, rgb.z, alpha);
    table->SetTableRange(0.0, 1.0);
    table->Build();
    mapper->SetLookupTable(table);
    mapper->SetScalarVisibility(true);
    mapper->SetScalarRange(0.0, 1.0);
    std::array<double, 3> voxels{}, pixels{};
    double lit = 0.0;
    VOXELGI_CHECK(scene.Measure(voxels, pixels, lit) == EXIT_SUCCESS, "not measured");
    ok = Transmits("lookup-table alpha " + std::to_string(alpha), rgb, alpha, voxels, pixels) &&
      ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

// The largest occupancy (albedo alpha) of the voxels around grid point (x, y, z), a voxel
// either way on each axis.
double Occupancy(vtkImageData* albedo, double x, double y, double z)
{
  const double* origin = albedo->GetOrigin();
  const double h = albedo->GetSpacing()[0];
  const int* dims = albedo->GetDimensions();
  const int centre[3] = { static_cast<int>(std::lround((x - origin[0]) / h)),
    static_cast<int>(std::lround((y - origin[1]) / h)),
    static_cast<int>(std::lround((z - origin[2]) / h)) };
  double largest = 0.0;
  for (int k = -1; k <= 1; ++k)
  {
    for (int j = -1; j <= 1; ++j)
    {
      for (int i = -1; i <= 1; ++i)
      {
        int ijk[3] = { centre[0] + i, centre[1] + j, centre[2] + k };
        if (ijk[0] >= 0 && ijk[1] >= 0 && ijk[2] >= 0 && ijk[0] < dims[0] && ijk[1] < dims[1] &&
          ijk[2] < dims[2])
        {
          largest = std::max(largest,
            albedo->GetPointData()->GetScalars()->GetComponent(albedo->ComputePointId(ijk), 3) /
              255.0);
        }
      }
    }
  }
  return largest;
}

// A plane of opacity a stops a of the light in its voxels (the albedo volume's alpha: the
// mean opacity of its fragments), the floor's voxels stay opaque; and a sunlit plane does not
// light the floor under it through itself: under an opaque one the floor's voxels keep less
// than a fifth of the open floor's light at the defaults (bounces on; only light the floor
// and the plane's underside pass on reaches it). Voxels that sent their light every way gave
// 0.58 there.
int PartialOccupancy()
{
  bool ok = true;
  for (const double alpha : { 0.25, 0.5, 0.75, 1.0 })
  {
    SunOverFloor scene;
    scene.AddPlane(1.0, dvec3(0.9, 0.6, 0.3), alpha);
    std::array<double, 3> voxels{}, pixels{};
    double lit = 0.0;
    VOXELGI_CHECK(scene.Measure(voxels, pixels, lit) == EXIT_SUCCESS, "not measured");
    vtkNew<vtkImageData> albedo;
    VOXELGI_CHECK(
      scene.View.GI->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, albedo), "no voxels");
    const double plane = Occupancy(albedo, 2.0, 1.0, 2.0);
    const double floor = Occupancy(albedo, 2.0, 0.0, 2.0);
    const std::string what = "opacity " + std::to_string(alpha);
    std::cout << what << ": the plane's voxels stop " << plane << ", the floor's " << floor
              << ", the floor's voxel light under the plane " << voxels[0]
              << " of the open floor's" << std::endl;
    ok = Within(what + ": error of the plane's occupancy", std::abs(plane - alpha), 0.01, 0.01) &&
      ok;
    ok = Within(what + ": the floor's lack of occupancy", 1.0 - floor, 0.0, 0.0) && ok;
    if (alpha == 1.0)
    {
      ok = Within("the floor's voxel light under a sunlit opaque plane, of the open floor's",
             voxels[0], 0.2, 0.2) && ok;
    }
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

// A translucent plane under the floor (the sun lights the floor before reaching it) takes no
// light from the floor, and VTK still draws a translucent plane over it.
int BehindTheReceiver()
{
  SunOverFloor alone;
  std::array<double, 3> voxels{}, pixels{};
  double lit = 0.0;
  VOXELGI_CHECK(alone.Measure(voxels, pixels, lit) == EXIT_SUCCESS, "not measured");
  SunOverFloor below;
  below.AddPlane(-1.0, dvec3(0.2, 0.2, 0.9), 0.9);
  below.AddPlane(-0.5, dvec3(0.9, 0.2, 0.2), 0.5);
  double litBelow = 0.0;
  VOXELGI_CHECK(below.Measure(voxels, pixels, litBelow) == EXIT_SUCCESS, "not measured");
  std::cout << "lit floor " << lit << ", with translucent planes under it " << litBelow
            << std::endl;
  bool ok = Within("floor's change from translucent planes behind it",
    std::abs(litBelow / lit - 1.0), 0.01, 0.01);
  for (int c = 0; c < 3; ++c)
  {
    ok = Within("floor under the planes, channel " + std::to_string(c),
           std::abs(pixels[c] - 1.0), 0.01, 0.01) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

// A translucent plane (colour c, opacity a) inside a closed box whose black walls emit
// radiance E: light E arrives from every side, so GI adds E c to VTK's colour of the plane,
// which VTK blends over the wall behind it with weight a: the plane's pixels gain a c E.
// Since the plane is in the voxels, its cones start above its own voxels and GI adds 0.90
// of that (goal within 10 %, asserted 12 %).
int LitByEmittingRoom()
{
  const double E = 0.5, alpha = 0.5;
  const dvec3 rgb(0.6, 0.5, 0.4);
  voxelgi_test::GIWindow view(nullptr, 64, 100, 0);
  // A light of no intensity: VTK shades the plane (its normal and position exist in its
  // shader), adding nothing.
  vtkNew<vtkLight> dark;
  dark->SetLightTypeToSceneLight();
  dark->SetIntensity(0.0);
  view.Renderer->AddLight(dark);
  voxelgi_test::AddEmittingBox(view.Renderer, 4.0, E);
  vtkActor* plane = voxelgi_test::AddQuad(view.Renderer, dvec3(1.0, 1.0, 2.0),
    dvec3(3.0, 1.0, 2.0), dvec3(1.0, 3.0, 2.0), rgb.x, rgb.y, rgb.z);
  plane->GetProperty()->SetOpacity(alpha);
  vtkCamera* camera = view.Renderer->GetActiveCamera();
  camera->SetPosition(2.0, 2.0, 3.9);
  camera->SetFocalPoint(2.0, 2.0, 2.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(40.0);
  view.Renderer->ResetCameraClippingRange();
  auto centre = [&view](bool gi, int c) {
    gi ? view.Window->Render() : view.RenderWithoutGI();
    vtkNew<vtkFloatArray> pixels;
    view.Window->GetRGBAPixelData(0, 0, 99, 99, 0, pixels);
    return voxelgi_test::MeanOver(pixels, 100, 40, 40, 60, 60, c);
  };
  bool ok = true;
  for (int c = 0; c < 3; ++c)
  {
    const double lit = centre(true, c);
    VOXELGI_CHECK(view.GI->GetGIActive() && voxelgi_test::AllFinite(view.GI), "GI did not run");
    const double plain = centre(false, c);
    const double expected = alpha * rgb[c] * E;
    std::cout << "channel " << c << ": plain " << plain << ", with GI " << lit << ", added "
              << lit - plain << " (a c E " << expected << ")" << std::endl;
    ok = Within("translucent plane lit by the room, channel " + std::to_string(c) +
             ", error of what GI adds",
           std::abs((lit - plain) / expected - 1.0), 0.1, 0.12) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
}

int TestGITranslucency(int argc, char* argv[])
{
  return voxelgi_test::RunCases({ { "PlaneTransmittance", PlaneTransmittance },
                                  { "ScalarColorsTransmittance", ScalarColorsTransmittance },
                                  { "BehindTheReceiver", BehindTheReceiver },
                                  { "PartialOccupancy", PartialOccupancy },
                                  { "LitByEmittingRoom", LitByEmittingRoom } },
    argc, argv);
}
