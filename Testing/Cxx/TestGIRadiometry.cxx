// Radiometry of the GI image against closed-form physics (issue 17), pixel by pixel on the
// read-back float images. Every expectation is computed here from the scene's geometry and
// materials, never from the pass:
//  Furnace        a closed box of albedo rho with uniform emission E, seen from inside: with B
//                 voxel bounces (+ the per-pixel gather) and no tail every pixel is
//                 E (1 - rho^(B+2)) / (1 - rho) -> E / (1 - rho); never above the limit, never
//                 darker with more bounces. AO off (AO multiplies VTK's direct term).
//  FurnaceDefaults the same at the default settings (AO on, BounceTail): from three bounces
//                 on, the tail makes every pixel the limit E / (1 - rho).
//  FurnaceAlbedoOne walls of albedo 1: the series E (B + 2) grows without limit; every pixel
//                 stays finite, at most E (B + 2), and grows with the bounces (no blow-up);
//                 the mean keeps most of it (each bounce passes the light on whole). With
//                 the tail (its ratio at most 0.9) at most E (B + 2) + 9 E, still finite.
//  AreaLight      one emissive square (radiance L, albedo 0) over a white plane (albedo rho):
//                 the plane's radiance is rho L F, F the point-to-parallel-rectangle form
//                 factor (closed form).
//  LitByFloor     a block on a floor lit straight down by a directional light, seen face on:
//                 its vertical face gets no direct light, only rho_b F L_floor from the floor
//                 (F: face point -> floor form factor, integrated from the kernel). Not black.
//  Contact        a small block on the same floor: the floor next to it must not be brighter
//                 than the floor without it (black block), nor brighter than the bound of the
//                 light its faces can reflect (white block).
//  ThinWall       a closed dark room sharing a one-voxel wall with a room whose other walls
//                 emit: no light reaches the dark room, every pixel is 0.
//  PointLightRoom a closed room wound outward (a vtkCubeSource) under a point light with
//                 inverse-square attenuation: each voxel bounce adds rho^B of the direct
//                 light's area mean (view factors of a closed room sum to one); with the
//                 tail, three bounces give the whole series, the direct mean / (1 - rho).
//                 At the default 128^3 and at a coarse 32^3.
//  WallStripes    the back wall of a closed room lit by an emissive ceiling panel: the light
//                 on it varies smoothly, so what a pixel differs from its 9 x 9 neighbourhood
//                 (stripes and bands at voxel spacing) is 0 relative to the wall's mean.
// Where the pass does not meet the physical tolerance yet, the test asserts the bound it meets
// today (a regression guard, a little above the measured error) and prints the goal beside it
// as "GOAL NOT MET" (docs/reference.md lists them).
// Each case runs alone when its name is given on the command line (ctest runs them one by
// one); the composited images are written to the test output directory (-T) as
// TestGIRadiometry-<case>.png.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace
{
using glm::dvec3;
using voxelgi_test::Within;
constexpr double Pi = 3.14159265358979323846;

std::string OutputDirectory = ".";

// The composited float image as an 8-bit PNG (clamped), for the person reading the log.
void SavePng(vtkFloatArray* rgba, int w, int h, const std::string& name)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(w, h, 1);
  vtkNew<vtkUnsignedCharArray> bytes;
  bytes->SetNumberOfComponents(3);
  bytes->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(w) * h; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = std::min(std::max(static_cast<double>(rgba->GetComponent(i, c)), 0.0), 1.0);
      bytes->SetComponent(i, c, std::floor(255.0 * v + 0.5));
    }
  }
  image->GetPointData()->SetScalars(bytes);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  const std::string path = OutputDirectory + "/TestGIRadiometry-" + name + ".png";
  writer->SetFileName(path.c_str());
  writer->Write();
}

// The world ray through the centre of pixel (x, y) (display coordinates, rows bottom up).
void PixelRay(vtkRenderer* renderer, int x, int y, dvec3& origin, dvec3& direction)
{
  dvec3 ends[2];
  for (int k = 0; k < 2; ++k)
  {
    renderer->SetDisplayPoint(x + 0.5, y + 0.5, k);
    renderer->DisplayToWorld();
    const double* w = renderer->GetWorldPoint();
    ends[k] = dvec3(w[0], w[1], w[2]) / w[3];
  }
  origin = ends[0];
  direction = glm::normalize(ends[1] - ends[0]);
}

// Ray parameter of the first hit of an axis-aligned box, or -1.
double HitBox(const dvec3& o, const dvec3& d, const dvec3& lo, const dvec3& hi)
{
  double t0 = 0.0, t1 = 1e30;
  for (int a = 0; a < 3; ++a)
  {
    if (std::abs(d[a]) < 1e-12)
    {
      if (o[a] < lo[a] || o[a] > hi[a])
      {
        return -1.0;
      }
      continue;
    }
    double ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
    if (ta > tb)
    {
      std::swap(ta, tb);
    }
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 <= t1 ? t0 : -1.0;
}

// Form factor from a differential area to a parallel rectangle of sides a, b at distance c,
// the area's foot under one corner (e.g. Howell's catalogue, B-3).
double CornerFormFactor(double a, double b, double c)
{
  const double A = a / c, B = b / c;
  const double sa = std::sqrt(1.0 + A * A), sb = std::sqrt(1.0 + B * B);
  return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2.0 * Pi);
}

// ... to the rectangle [x0, x1] x [z0, z1] at height c above the point (px, pz): signed
// sums of the four corner rectangles.
double RectangleFormFactor(double px, double pz, double x0, double x1, double z0, double z1, double c)
{
  auto part = [c](double u, double v) {
    // rectangle from the foot to the corner (u, v), signed by the quadrant
    if (u == 0.0 || v == 0.0)
    {
      return 0.0;
    }
    const double s = (u > 0.0 ? 1.0 : -1.0) * (v > 0.0 ? 1.0 : -1.0);
    return s * CornerFormFactor(std::abs(u), std::abs(v), c);
  };
  return part(x1 - px, z1 - pz) - part(x0 - px, z1 - pz) - part(x1 - px, z0 - pz) +
    part(x0 - px, z0 - pz);
}

// Form factor from a differential area at p with unit normal n to the floor rectangle
// [x0, x1] x [z0, z1] (y = 0, normal +y), integrated from the kernel cos cos / (pi r^2) on a
// grid refined toward the area (midpoint rule in a stretched coordinate).
double FloorFormFactor(const dvec3& p, const dvec3& n, double x0, double x1, double z0, double z1)
{
  const int nx = 600, nz = 600;
  double sum = 0.0;
  // z stretched as z0 + (z1 - z0) s^3 when the area stands on the z0 edge (the kernel is
  // singular there), x uniform.
  for (int j = 0; j < nz; ++j)
  {
    const double s0 = double(j) / nz, s1 = double(j + 1) / nz;
    const double za = z0 + (z1 - z0) * s0 * s0 * s0, zb = z0 + (z1 - z0) * s1 * s1 * s1;
    const double z = 0.5 * (za + zb), dz = zb - za;
    for (int i = 0; i < nx; ++i)
    {
      const double x = x0 + (x1 - x0) * (i + 0.5) / nx, dx = (x1 - x0) / nx;
      const dvec3 r = dvec3(x, 0.0, z) - p;
      const double r2 = glm::dot(r, r);
      const double cos1 = glm::dot(n, r) / std::sqrt(r2);
      const double cos2 = -r.y / std::sqrt(r2);
      if (cos1 > 0.0 && cos2 > 0.0)
      {
        sum += cos1 * cos2 / (Pi * r2) * dx * dz;
      }
    }
  }
  return sum;
}

struct View : voxelgi_test::GIWindow
{
  int Size = 0;

  // Pixels are compared with closed forms one by one: no multisampled blends at edges.
  View(int size, int resolution)
    : GIWindow(nullptr, resolution, size, 0)
    , Size(size)
  {
  }
  void Aim(const dvec3& position, const dvec3& focal, double viewAngle = 30.0)
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(position.x, position.y, position.z);
    camera->SetFocalPoint(focal.x, focal.y, focal.z);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(viewAngle);
    this->Renderer->ResetCameraClippingRange();
  }
  // Render and read back the composite and indirect images; false if GI did not trace.
  bool Render(vtkFloatArray* composite, vtkFloatArray* indirect)
  {
    this->Window->Render();
    return this->GI->GetGIActive() && voxelgi_test::AllFinite(this->GI) &&
      this->GI->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, composite) &&
      (!indirect || this->GI->GetFloatImage(vtkVoxelGIPass::IMAGE_INDIRECT, indirect));
  }
};

// An emitter as the project's scenes make them: VTK draws it unlit at its radiance (ambient
// colour, in a renderer without lights), the pass lights the scene with it.
void MakeEmitter(vtkActor* actor, double emission, bool reflects)
{
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetAmbientColor(emission, emission, emission);
  if (!reflects)
  {
    actor->GetProperty()->SetDiffuse(0.0);
  }
  vtkVoxelGIPass::SetPropEmission(actor, emission, emission, emission);
}

struct Stats
{
  double Min = 1e30, Max = -1e30, Sum = 0.0;
  int N = 0;
  void Add(double v)
  {
    this->Min = std::min(this->Min, v);
    this->Max = std::max(this->Max, v);
    this->Sum += v;
    ++this->N;
  }
  double Mean() const { return this->N ? this->Sum / this->N : 0.0; }
};

//------------------------------------------------------------------------------
// Pixel furnace: closed box [0, 4]^3, walls of albedo rho emitting E, camera inside.
int FurnaceCase(bool defaults)
{
  const double E = 0.5, rho = 0.5, limit = E / (1.0 - rho);
  const int size = 64;
  View view(size, 32);
  view.Renderer->AutomaticLightCreationOff();
  for (vtkActor* wall : voxelgi_test::AddClosedBox(view.Renderer, 4.0, rho))
  {
    MakeEmitter(wall, E, true);
  }
  if (!defaults)
  {
    view.GI->SetAmbientOcclusionStrength(0.0);
    view.GI->SetBounceTail(false);
  }
  view.Aim(dvec3(2.0, 2.0, 3.5), dvec3(2.0, 2.0, 0.0), 60.0);
  const char* label = defaults ? "furnace (defaults)" : "furnace (AO off)";

  std::vector<float> previous;
  bool ok = true;
  for (int bounces : { 0, 1, 2, 4, 10 })
  {
    view.GI->SetBounces(bounces);
    vtkNew<vtkFloatArray> composite, indirect;
    VOXELGI_CHECK(view.Render(composite, indirect), "GI did not run");
    // B voxel bounces, then the pixel's own gather: B + 2 terms of the Neumann series; the
    // tail (at the defaults, measured from three bounces on) adds the rest.
    const bool tail = defaults && bounces >= 3;
    const double expected = tail ? limit : E * (1.0 - std::pow(rho, bounces + 2)) / (1.0 - rho);
    Stats all, ind;
    double worst = 0.0;
    int darker = 0;
    std::vector<float> current(static_cast<std::size_t>(size) * size);
    for (vtkIdType i = 0; i < size * size; ++i)
    {
      const double v = composite->GetComponent(i, 0);
      all.Add(v);
      ind.Add(indirect->GetComponent(i, 0));
      worst = std::max(worst, std::abs(v - expected) / expected);
      current[i] = static_cast<float>(v);
      if (!previous.empty() && v < previous[i] - 2e-3)
      {
        ++darker;
      }
    }
    std::cout << label << ", " << bounces << " bounces: pixels min " << all.Min << " mean "
              << all.Mean() << " max " << all.Max << " (expected " << expected << ", limit "
              << limit << "; mean/expected " << all.Mean() / expected << ", worst relative error "
              << worst << "); indirect mean " << ind.Mean() << " (expected "
              << expected - E << "); pixels darker than with fewer bounces: " << darker
              << std::endl;
    if (bounces == 10)
    {
      SavePng(composite, size, size, defaults ? "FurnaceDefaults" : "Furnace");
    }
    // half floats round to 1/1024 relative; measured 1.0029 since the mipmaps average a texel
    // over its part inside the scene's bounds (docs/reference.md), 0.997 before
    if (all.Max > limit * 1.004)
    {
      std::cerr << "FAILED: " << label << ": pixels brighter than the furnace limit" << std::endl;
      ok = false;
    }
    if (darker > 0)
    {
      std::cerr << "FAILED: " << label << ": pixels darker with more bounces" << std::endl;
      ok = false;
    }
    // every pixel within a few percent of the series at this bounce count (measured: 0.132,
    // the box's corners; 0.168 before the composite gathered over the cone turns; the same
    // at the defaults: AO leaves the emitters' light alone; it was 0.376 while AO multiplied
    // all of VTK's colour)
    ok = Within(std::string(label) + ", " + std::to_string(bounces) +
           " bounces, largest relative error", worst, 0.03, 0.16) && ok;
    // measured: mean 0.991 of the series, with AO off and at the defaults (0.911 while a
    // cone's last sample read a wall obliquely and cones stopped at one grid size; 0.741
    // before that)
    ok = Within(std::string(label) + ", " + std::to_string(bounces) + " bounces, error of the mean",
           std::abs(all.Mean() / expected - 1.0), 0.03, 0.03) && ok;
    previous = current;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

//------------------------------------------------------------------------------
// A closed room of one albedo under a point light with inverse-square attenuation, built as
// programs build rooms: a vtkCubeSource, its faces wound outward (seen from inside). In a
// closed room every wall sees the others with view factors summing to one, so the area mean
// of the radiance after B bounces is M0 (1 + rho + ... + rho^B): bounce B adds rho^B M0,
// M0 the mean of the direct light. The voxels' radiance is the area mean (walls of even
// thickness). `bounceBound` and `seriesBound`: the errors asserted today at this resolution
// (the goal is 0.05 for both).
int PointLightRoom(int resolution, double bounceBound, double seriesBound)
{
  const double rho = 0.5;
  const std::string room = "point-light room at " + std::to_string(resolution) + "^3";
  View view(48, resolution);
  view.Renderer->AutomaticLightCreationOff();
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(0.0, 4.0, 0.0, 2.4, 0.0, 4.0);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkActor> walls;
  walls->SetMapper(mapper);
  walls->GetProperty()->SetColor(rho, rho, rho);
  walls->GetProperty()->SetAmbient(0.0);
  walls->GetProperty()->SetSpecular(0.0);
  view.Renderer->AddActor(walls);
  vtkNew<vtkLight> lamp;
  lamp->SetLightTypeToSceneLight();
  lamp->SetPositional(true);
  lamp->SetConeAngle(180.0);
  lamp->SetPosition(1.3, 1.6, 2.2);
  lamp->SetFocalPoint(1.3, 0.0, 2.2);
  lamp->SetAttenuationValues(0.0, 0.0, 1.0);
  view.Renderer->AddLight(lamp);
  view.Aim(dvec3(3.5, 1.2, 3.5), dvec3(0.5, 1.0, 0.5), 80.0);
  auto meanRadiance = [&view]() {
    vtkNew<vtkImageData> radiance;
    if (!view.GI->GetVoxelVolume(vtkVoxelGIPass::VOLUME_RADIANCE, radiance))
    {
      return -1.0;
    }
    vtkDataArray* values = radiance->GetPointData()->GetScalars();
    Stats occupied;
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    {
      if (values->GetComponent(i, 3) > 0.0)
      {
        occupied.Add(values->GetComponent(i, 0));
      }
    }
    return occupied.Mean();
  };
  bool ok = true;
  double m0 = 0.0, previous = 0.0;
  view.GI->SetBounceTail(false);
  for (int bounces : { 0, 1, 2, 3 })
  {
    view.GI->SetBounces(bounces);
    vtkNew<vtkFloatArray> composite;
    VOXELGI_CHECK(view.Render(composite, nullptr), room << ": GI did not run");
    const double m = meanRadiance();
    VOXELGI_CHECK(m > 0.0, room << ": no voxel radiance");
    m0 = bounces == 0 ? m : m0;
    if (bounces > 0)
    {
      const double added = (m - previous) / (std::pow(rho, bounces) * m0);
      std::cout << room << ", bounce " << bounces << ": voxel mean " << m << " adds " << added
                << " of rho^B M0 (mean of the direct light " << m0 << ")" << std::endl;
      ok = Within(room + ", bounce " + std::to_string(bounces) + ", error of what it adds",
             std::abs(added - 1.0), 0.05, bounceBound) &&
        ok;
    }
    if (bounces == 3)
    {
      SavePng(composite, view.Size, view.Size, "PointLightRoom" + std::to_string(resolution));
    }
    previous = m;
  }
  view.GI->SetBounceTail(true);
  vtkNew<vtkFloatArray> composite;
  VOXELGI_CHECK(view.Render(composite, nullptr), room << ": GI did not run");
  const double converged = meanRadiance() / (m0 / (1.0 - rho));
  std::cout << room << ", 3 bounces and the tail: voxel mean " << converged
            << " of the whole series M0 / (1 - rho)" << std::endl;
  ok = Within(room + ", 3 bounces and the tail, error against the whole series",
         std::abs(converged - 1.0), 0.05, seriesBound) &&
    ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

// The room at the default resolution and at 32^3, where its 4 x 2.4 x 4 units are about
// 29 x 17 x 29 voxels and a texel of the coarser mip levels spans a fifth of its height or
// more.
// Measured at 128^3: bounces add 1.001, 1.006, 1.007 of rho^B M0, the series 1.003 (64^3:
// 1.011, 1.016, 1.012 and 1.007). At 32^3: 1.098, 1.129, 1.136 and 1.062 (1.044, 1.022,
// 0.979 and 1.009 before the mipmaps' average inside the scene's bounds and correlated
// coverage: a texel at the room's walls averages over few columns there); 0.0003 while the
// bounce gathered over the winding's side, out of the room.
int PointLightRoomCase()
{
  const int fine = PointLightRoom(128, 0.05, 0.05);
  const int coarse = PointLightRoom(32, 0.15, 0.07);
  return fine == EXIT_SUCCESS && coarse == EXIT_SUCCESS ? EXIT_SUCCESS : EXIT_FAILURE;
}

//------------------------------------------------------------------------------
// One emissive square over a white plane, no light.
int AreaLightCase()
{
  const double L = 3.0, rho = 0.8, h = 1.0, half = 0.6;
  const int size = 120;
  View view(size, 64);
  view.Renderer->AutomaticLightCreationOff();
  voxelgi_test::AddQuad(view.Renderer, dvec3(-2, 0, -2), dvec3(-2, 0, 2), dvec3(2, 0, -2), rho, rho, rho);
  vtkActor* panel = voxelgi_test::AddQuad(view.Renderer, dvec3(-half, h, -half),
    dvec3(half, h, -half), dvec3(-half, h, half), 1.0, 1.0, 1.0);
  MakeEmitter(panel, L, false);
  view.Aim(dvec3(0.0, 2.0, 4.6), dvec3(0.0, 0.0, 0.2), 40.0);
  vtkNew<vtkFloatArray> composite, indirect;
  VOXELGI_CHECK(view.Render(composite, indirect), "GI did not run");
  SavePng(composite, size, size, "AreaLight");

  // plane pixels not hidden by the panel, away from the plane's edges
  Stats ratio, under, measured, expected;
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      dvec3 o, d;
      PixelRay(view.Renderer, x, y, o, d);
      if (d.y >= -1e-6)
      {
        continue;
      }
      const double t = -o.y / d.y;
      const dvec3 p = o + t * d;
      const double tp = (h - o.y) / d.y;
      const dvec3 q = o + tp * d;
      const bool hidden = tp > 0.0 && tp < t && std::abs(q.x) <= half + 0.05 && std::abs(q.z) <= half + 0.05;
      if (hidden || std::abs(p.x) > 1.6 || std::abs(p.z) > 1.6)
      {
        continue;
      }
      const double F = RectangleFormFactor(p.x, p.z, -half, half, -half, half, h);
      const double truth = rho * L * F;
      const double v = composite->GetComponent(static_cast<vtkIdType>(y) * size + x, 0);
      ratio.Add(v / truth);
      measured.Add(v);
      expected.Add(truth);
      if (std::abs(p.x) < half && std::abs(p.z) < half)
      {
        under.Add(v / truth);
      }
    }
  }
  std::cout << "area light: " << ratio.N << " plane pixels; measured mean " << measured.Mean()
            << " vs rho L F mean " << expected.Mean() << " (ratio of means "
            << measured.Mean() / expected.Mean() << "); per-pixel ratio min " << ratio.Min
            << " mean " << ratio.Mean() << " max " << ratio.Max << "; under the panel ("
            << under.N << " px) ratio min " << under.Min << " mean " << under.Mean() << " max "
            << under.Max << "; rho L F at the centre "
            << rho * L * RectangleFormFactor(0, 0, -half, half, -half, half, h) << std::endl;
  VOXELGI_CHECK(ratio.N > 500, "too few plane pixels in view");
  VOXELGI_CHECK(under.N > 20, "too few plane pixels under the panel in view");
  bool ok = true;
  // measured: mean 1.068 of rho L F; under the panel 1.04 .. 1.15 (0.942 and 0.89 .. 1.06
  // before emission was weighted by coverage and cones ended at the scene's face, which the
  // panel closes here; 0.883 and 0.76 .. 1.07 with six cones)
  ok = Within("area light, error of the plane's mean radiance",
         std::abs(measured.Mean() / expected.Mean() - 1.0), 0.10, 0.10) && ok;
  ok = Within("area light, largest error under the panel",
         std::max(1.0 - under.Min, under.Max - 1.0), 0.20, 0.20) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

//------------------------------------------------------------------------------
// Floor [-3, 3]^2 (albedo rhoFloor) lit straight down by a directional light of intensity 1.
vtkActor* AddLitFloor(vtkRenderer* renderer, double rhoFloor)
{
  vtkActor* floor = voxelgi_test::AddQuad(
    renderer, dvec3(-3, 0, -3), dvec3(-3, 0, 3), dvec3(3, 0, -3), rhoFloor, rhoFloor, rhoFloor);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(0.0, 10.0, 0.0);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  sun->SetIntensity(1.0);
  renderer->AddLight(sun);
  return floor;
}

vtkActor* AddBlock(vtkRenderer* renderer, const dvec3& lo, const dvec3& hi, double rho)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(lo.x, hi.x, lo.y, hi.y, lo.z, hi.z);
  return vtkVoxelGIScenes::AddSource(renderer, cube, rho, rho, rho);
}

int LitByFloorCase()
{
  const double rhoFloor = 0.8, rhoBlock = 0.8;
  const dvec3 lo(-0.75, 0.0, -0.75), hi(0.75, 1.5, 0.75);
  const int size = 120;
  View view(size, 64);
  AddLitFloor(view.Renderer, rhoFloor);
  AddBlock(view.Renderer, lo, hi, rhoBlock);
  view.Aim(dvec3(0.0, 0.75, 5.0), dvec3(0.0, 0.75, 0.0), 30.0);
  vtkNew<vtkFloatArray> composite, indirect;
  VOXELGI_CHECK(view.Render(composite, indirect), "GI did not run");
  SavePng(composite, size, size, "LitByFloor");

  // the +z face, rows by height: measured against rho_b F(y) L_floor with L_floor = rho_f x 1
  const int bands = 6;
  Stats band[bands], truthBand[bands], ratio;
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      dvec3 o, d;
      PixelRay(view.Renderer, x, y, o, d);
      const double t = (hi.z - o.z) / d.z;
      const dvec3 p = o + t * d;
      // inside the face, a little away from its edges
      if (!(t > 0.0) || std::abs(p.x) > 0.65 || p.y < 0.02 || p.y > 1.45)
      {
        continue;
      }
      const int b = std::min(bands - 1, static_cast<int>(p.y / 1.5 * bands));
      const double v = composite->GetComponent(static_cast<vtkIdType>(y) * size + x, 0);
      band[b].Add(v);
      // lit floor in front of the face (under the block it is dark, the face does not see it)
      const double F = FloorFormFactor(dvec3(p.x, p.y, hi.z), dvec3(0, 0, 1), -3.0, 3.0, hi.z, 3.0);
      const double truth = rhoBlock * F * rhoFloor;
      truthBand[b].Add(truth);
      ratio.Add(v / truth);
    }
  }
  VOXELGI_CHECK(ratio.N > 300, "too few face pixels in view");
  std::cout << "lit by the floor: " << ratio.N << " face pixels, measured / (rho_b F rho_f I) min "
            << ratio.Min << " mean " << ratio.Mean() << " max " << ratio.Max << std::endl;
  bool ok = true;
  for (int b = 0; b < bands; ++b)
  {
    std::cout << "  height " << (b + 0.5) * 1.5 / bands << ": measured " << band[b].Mean()
              << " (min " << band[b].Min << "), expected " << truthBand[b].Mean()
              << ", ratio " << band[b].Mean() / truthBand[b].Mean() << std::endl;
    // second-order light (face -> floor -> face) adds a few percent to the expectation;
    // measured: 1.05 .. 1.07 (top) .. 1.36 (next to the floor, seen too early through wide
    // samples)
    ok = Within("lit by the floor, error at height " + std::to_string((b + 0.5) * 1.5 / bands),
           std::abs(band[b].Mean() / truthBand[b].Mean() - 1.0), 0.25, 0.42) && ok;
  }
  if (ratio.Min < 0.5)
  {
    std::cerr << "FAILED: lit by the floor: face pixels darker than half the form factor's light" << std::endl;
    ok = false;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

//------------------------------------------------------------------------------
// Contact: the floor around a small block, with and without the block.
int ContactCase(double rhoBlock, const char* name)
{
  const double rhoFloor = 0.8;
  const dvec3 lo(-0.4, 0.0, -0.4), hi(0.4, 0.5, 0.4);
  const int size = 120;
  View view(size, 64);
  AddLitFloor(view.Renderer, rhoFloor);
  vtkActor* block = AddBlock(view.Renderer, lo, hi, rhoBlock);
  // a second, far block keeps the grid the same with and without the first
  AddBlock(view.Renderer, dvec3(2.6, 0.0, -2.9), dvec3(2.9, 0.5, -2.6), 0.0);
  view.Aim(dvec3(0.0, 3.0, 2.6), dvec3(0.0, 0.0, 0.0), 30.0);
  vtkNew<vtkFloatArray> with, without, indirect;
  VOXELGI_CHECK(view.Render(with, indirect), "GI did not run");
  SavePng(with, size, size, name);
  const double voxel = view.GI->GetGridVoxelSize();
  block->SetVisibility(false);
  VOXELGI_CHECK(view.Render(without, nullptr), "GI did not run without the block");

  // Light straight down: the block's vertical faces get only what the floor reflects to
  // them, at most rho_b rho_f I / 2 (half their hemisphere is floor); the floor next to them
  // gets at most half its hemisphere's worth of that back: a relative excess k / (1 - k)
  // with k = rho_f rho_b / 4 over all orders. A black block reflects nothing: no excess.
  const double k = rhoFloor * rhoBlock / 4.0;
  const double bound = k / (1.0 - k);
  Stats excess, near;
  int brighter = 0;
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      dvec3 o, d;
      PixelRay(view.Renderer, x, y, o, d);
      if (HitBox(o, d, lo, hi) >= 0.0 || d.y >= 0.0)
      {
        continue;
      }
      const dvec3 p = o - o.y / d.y * d;
      const double gap = std::max(std::abs(p.x) - hi.x, std::abs(p.z) - hi.z);
      if (gap <= 0.0 || gap > 4.0 * voxel)
      {
        continue;
      }
      const vtkIdType i = static_cast<vtkIdType>(y) * size + x;
      const double a = with->GetComponent(i, 0), b = without->GetComponent(i, 0);
      excess.Add(a / b - 1.0);
      near.Add(a);
      if (a > b * (1.0 + bound) + 1e-3)
      {
        ++brighter;
      }
    }
  }
  VOXELGI_CHECK(excess.N > 100, "too few floor pixels around the block");
  std::cout << name << " (block albedo " << rhoBlock << "): " << excess.N
            << " floor pixels within 4 voxels of the block; with / without - 1: min "
            << excess.Min << " mean " << excess.Mean() << " max " << excess.Max
            << " (physical bound " << bound << "); floor radiance there min " << near.Min
            << " max " << near.Max << " (lit floor rho_f I = " << rhoFloor
            << "); pixels above the bound: " << brighter << std::endl;
  // Measured: nothing beyond the bound with either block (a white block added up to 0.012
  // at its base with six cones, whose wide near samples saw its lit face too early).
  return Within(std::string(name) + ", largest excess beyond what the block can reflect",
           std::max(excess.Max - bound, 0.0), 0.0, 0.0)
    ? EXIT_SUCCESS
    : EXIT_FAILURE;
}

//------------------------------------------------------------------------------
// Furnace of albedo 1: nothing is absorbed, so each bounce adds E at most.
int FurnaceAlbedoOneCase()
{
  const double E = 0.5;
  const int size = 64;
  View view(size, 32);
  view.Renderer->AutomaticLightCreationOff();
  for (vtkActor* wall : voxelgi_test::AddClosedBox(view.Renderer, 4.0, 1.0))
  {
    MakeEmitter(wall, E, true);
  }
  view.Aim(dvec3(2.0, 2.0, 3.5), dvec3(2.0, 2.0, 0.0), 60.0);
  view.GI->SetBounceTail(false);
  double previousMean = 0.0;
  for (int bounces : { 0, 1, 4, 10 })
  {
    view.GI->SetBounces(bounces);
    vtkNew<vtkFloatArray> composite;
    VOXELGI_CHECK(view.Render(composite, nullptr), "GI did not run");
    Stats all;
    for (vtkIdType i = 0; i < static_cast<vtkIdType>(size) * size; ++i)
    {
      all.Add(composite->GetComponent(i, 0));
    }
    const double series = E * (bounces + 2);
    std::cout << "furnace of albedo 1, " << bounces << " bounces: pixels min " << all.Min
              << " mean " << all.Mean() << " max " << all.Max << " (series " << series << ")"
              << std::endl;
    // half floats round to 1/1024 relative
    VOXELGI_CHECK(all.Max <= series * 1.002, "brighter than the series: energy created");
    VOXELGI_CHECK(all.Mean() > previousMean, "more bounces did not add light");
    previousMean = all.Mean();
    // measured: 0.932 of the series at ten bounces (0.958 before a face's last read raised
    // the cone's opacity instead of adding to it; 0.60 while each bounce lost a tenth)
    if (!Within("furnace of albedo 1, " + std::to_string(bounces) +
          " bounces, mean short of the series", 1.0 - all.Mean() / series, 0.03, 0.08))
    {
      return EXIT_FAILURE;
    }
  }
  // Nothing is absorbed, so the increments do not fall: the tail's ratio stops at 0.9, nine
  // times the last increment (at most E) more.
  view.GI->SetBounceTail(true);
  view.GI->SetBounces(4);
  vtkNew<vtkFloatArray> composite;
  VOXELGI_CHECK(view.Render(composite, nullptr), "GI did not run");
  Stats all;
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(size) * size; ++i)
  {
    all.Add(composite->GetComponent(i, 0));
  }
  std::cout << "furnace of albedo 1, 4 bounces and the tail: pixels min " << all.Min << " mean "
            << all.Mean() << " max " << all.Max << " (bound " << E * 15.0 << ")" << std::endl;
  VOXELGI_CHECK(std::isfinite(all.Max) && all.Max <= E * 15.0 * 1.002,
    "the tail made the albedo-1 furnace brighter than its bound");
  return EXIT_SUCCESS;
}

//------------------------------------------------------------------------------
// Thin wall: the dark room [0, 4]^3 and the bright room [4, 8] x [0, 4]^2 share the wall x = 4.
int ThinWallCase()
{
  const double S = 4.0, E = 1.0, rho = 0.5;
  const int size = 64;
  View view(size, 64);
  view.Renderer->AutomaticLightCreationOff();
  voxelgi_test::AddClosedBox(view.Renderer, S, rho);
  const dvec3 bright[5][3] = { { { S, 0, 0 }, { S, 0, S }, { 2 * S, 0, 0 } },
    { { S, S, 0 }, { 2 * S, S, 0 }, { S, S, S } }, { { S, 0, 0 }, { 2 * S, 0, 0 }, { S, S, 0 } },
    { { S, 0, S }, { S, S, S }, { 2 * S, 0, S } },
    { { 2 * S, 0, 0 }, { 2 * S, 0, S }, { 2 * S, S, 0 } } };
  for (const auto& q : bright)
  {
    MakeEmitter(voxelgi_test::AddQuad(view.Renderer, q[0], q[1], q[2], rho, rho, rho), E, true);
  }
  view.Aim(dvec3(0.4, 2.0, 2.0), dvec3(S, 2.0, 2.0), 70.0);
  vtkNew<vtkFloatArray> composite;
  VOXELGI_CHECK(view.Render(composite, nullptr), "GI did not run");
  SavePng(composite, size, size, "ThinWall");
  Stats all;
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(size) * size; ++i)
  {
    all.Add(composite->GetComponent(i, 0));
  }
  std::cout << "dark room next to a room of emission " << E << " through a wall of "
            << view.GI->GetGridVoxelSize() << " thick (one voxel): pixels mean "
            << all.Mean() << ", max " << all.Max << " (physically 0)" << std::endl;
  // measured: mean 0.0203, max 0.084 (0.0102 and 0.091 before the mipmaps' correlated
  // coverage and the cones' arrival-step correction, docs/reference.md; 0.009 before cones
  // ended at the scene's face; 0.20 before the composite gathered over neighbours)
  // where the shared wall meets the dark room's other walls (the wall's middle stays dark:
  // the directional mipmaps keep its two sides apart)
  return Within("thin wall, mean light in the dark room / E", all.Mean() / E, 0.01, 0.022) &&
      Within("thin wall, brightest pixel in the dark room / E", all.Max / E, 0.05, 0.12)
    ? EXIT_SUCCESS
    : EXIT_FAILURE;
}

//------------------------------------------------------------------------------
// Stripes: the back wall z = 0 of a closed room [0, 4]^3 of albedo 0.75 under an emissive
// ceiling panel, seen straight on from inside.
int WallStripesCase()
{
  const double S = 4.0, L = 10.0;
  const int size = 120;
  View view(size, 64);
  view.Renderer->AutomaticLightCreationOff();
  voxelgi_test::AddClosedBox(view.Renderer, S, 0.75);
  vtkActor* panel = voxelgi_test::AddQuad(view.Renderer, dvec3(1.5, S - 0.01, 1.5),
    dvec3(2.5, S - 0.01, 1.5), dvec3(1.5, S - 0.01, 2.5), 1.0, 1.0, 1.0);
  MakeEmitter(panel, L, false);
  view.Aim(dvec3(2.0, 2.0, 3.9), dvec3(2.0, 2.0, 0.0), 70.0);
  vtkNew<vtkFloatArray> composite;
  VOXELGI_CHECK(view.Render(composite, nullptr), "GI did not run");
  SavePng(composite, size, size, "WallStripes");
  // luminance of the pixels that see the wall's inner part (0.3 from its edges)
  std::vector<double> wall(static_cast<std::size_t>(size) * size, -1.0);
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      dvec3 o, d;
      PixelRay(view.Renderer, x, y, o, d);
      const dvec3 p = o - o.z / d.z * d;
      if (d.z < 0.0 && p.x > 0.3 && p.x < S - 0.3 && p.y > 0.3 && p.y < S - 0.3)
      {
        const vtkIdType i = static_cast<vtkIdType>(y) * size + x;
        wall[i] = (composite->GetComponent(i, 0) + composite->GetComponent(i, 1) +
                    composite->GetComponent(i, 2)) / 3.0;
      }
    }
  }
  Stats level, residual;
  for (int y = 4; y < size - 4; ++y)
  {
    for (int x = 4; x < size - 4; ++x)
    {
      const double v = wall[static_cast<std::size_t>(y) * size + x];
      double sum = 0.0;
      int n = 0;
      for (int j = -4; j <= 4; ++j)
      {
        for (int i = -4; i <= 4; ++i)
        {
          const double w = wall[static_cast<std::size_t>(y + j) * size + x + i];
          sum += w;
          n += w >= 0.0 ? 1 : 0;
        }
      }
      if (v < 0.0 || n < 81)
      {
        continue;
      }
      level.Add(v);
      residual.Add((v - sum / n) * (v - sum / n));
    }
  }
  VOXELGI_CHECK(level.N > 2000, "too few wall pixels in view: " << level.N);
  const double roughness = std::sqrt(residual.Mean()) / level.Mean();
  std::cout << "back wall: " << level.N << " pixels, mean " << level.Mean() << ", min "
            << level.Min << ", max " << level.Max << "; RMS difference from the 9 x 9 mean "
            << roughness << " of the mean" << std::endl;
  // measured: 0.015 with sixteen cones turned four ways over each 2 x 2 pixels (0.030 with
  // one fixed set, whose directions pick the thin panel's light up in spots and streaks; 0.013
  // with a single cone along the normal: the coarse mips' trilinear interpolation); 0.018 since
  // cones end at a closed room's walls in the texels that hold them (the walls' light is
  // gathered in full, in coarse texels)
  return Within("wall stripes, RMS difference from the neighbourhood / mean", roughness, 0.01,
           0.021)
    ? EXIT_SUCCESS
    : EXIT_FAILURE;
}

struct Case
{
  const char* Name;
  std::function<int()> Run;
};
}

int TestGIRadiometry(int argc, char* argv[])
{
  const Case cases[] = {
    { "Furnace", [] { return FurnaceCase(false); } },
    { "FurnaceDefaults", [] { return FurnaceCase(true); } },
    { "FurnaceAlbedoOne", FurnaceAlbedoOneCase },
    { "AreaLight", AreaLightCase },
    { "LitByFloor", LitByFloorCase },
    { "ContactBlack", [] { return ContactCase(0.0, "ContactBlack"); } },
    { "ContactWhite", [] { return ContactCase(0.8, "ContactWhite"); } },
    { "ThinWall", ThinWallCase },
    { "WallStripes", WallStripesCase },
    { "PointLightRoom", PointLightRoomCase },
  };
  std::vector<std::string> selected;
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "-T") == 0 && i + 1 < argc)
    {
      OutputDirectory = argv[++i];
    }
    else if (argv[i][0] != '-')
    {
      selected.emplace_back(argv[i]);
    }
    else if (i + 1 < argc && argv[i + 1][0] != '-')
    {
      ++i; // the value of another option (-D, -V)
    }
  }
  int failed = 0, ran = 0;
  for (const Case& c : cases)
  {
    if (!selected.empty() && std::find(selected.begin(), selected.end(), c.Name) == selected.end())
    {
      continue;
    }
    ++ran;
    std::cout << "== " << c.Name << std::endl;
    if (c.Run() != EXIT_SUCCESS)
    {
      std::cerr << "ERROR: case " << c.Name << " failed" << std::endl;
      ++failed;
    }
  }
  if (ran == 0)
  {
    std::cerr << "ERROR: no case named on the command line exists" << std::endl;
    return EXIT_FAILURE;
  }
  return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
