#include "vtkVoxelGIScenes.h"

#include "vtkVoxelGIPass.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkAssignAttribute.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkContourFilter.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkElevationFilter.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3D.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLineSource.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkRTAnalyticSource.h"
#include "vtkSphereSource.h"
#include "vtkStreamTracer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"
#include "vtkTubeFilter.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

vtkStandardNewMacro(vtkVoxelGIScenes);

namespace
{
constexpr double Size = 5.5;

using Vec3 = std::array<double, 3>;

// A quad from `origin` spanned by p1 and p2; its normal (p1 - o) x (p2 - o) faces the inside.
vtkActor* AddQuad(vtkRenderer* renderer, const Vec3& o, const Vec3& p1, const Vec3& p2,
  const Vec3& color)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(o[0], o[1], o[2]);
  plane->SetPoint1(p1[0], p1[1], p1[2]);
  plane->SetPoint2(p2[0], p2[1], p2[2]);
  return vtkVoxelGIScenes::AddSource(renderer, plane, color[0], color[1], color[2]);
}

// A box standing on y = 0, centred on (cx, cz), turned by `angle` degrees about y.
vtkActor* AddBlock(vtkRenderer* renderer, double cx, double cz, double sx, double sy, double sz,
  double angle, const Vec3& color)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(sx);
  cube->SetYLength(sy);
  cube->SetZLength(sz);
  vtkNew<vtkTransform> transform;
  transform->Translate(cx, 0.5 * sy, cz);
  transform->RotateY(angle);
  vtkNew<vtkTransformPolyDataFilter> place;
  place->SetInputConnection(cube->GetOutputPort());
  place->SetTransform(transform);
  return vtkVoxelGIScenes::AddSource(renderer, place, color[0], color[1], color[2]);
}

// Floor, ceiling, back, left and right walls of the box [x0, x1] x [y0, y1] x [z0, z1], open
// toward +z, normals inward. Returns the floor.
vtkActor* AddRoom(vtkRenderer* renderer, const Vec3& lo, const Vec3& hi, const Vec3& floor,
  const Vec3& walls, const Vec3& left, const Vec3& right)
{
  vtkActor* floorActor =
    AddQuad(renderer, lo, { lo[0], lo[1], hi[2] }, { hi[0], lo[1], lo[2] }, floor);
  AddQuad(renderer, { lo[0], hi[1], lo[2] }, { hi[0], hi[1], lo[2] }, { lo[0], hi[1], hi[2] },
    walls);
  AddQuad(renderer, lo, { hi[0], lo[1], lo[2] }, { lo[0], hi[1], lo[2] }, walls);
  AddQuad(renderer, lo, { lo[0], hi[1], lo[2] }, { lo[0], lo[1], hi[2] }, left);
  AddQuad(renderer, { hi[0], lo[1], lo[2] }, { hi[0], lo[1], hi[2] }, { hi[0], hi[1], lo[2] },
    right);
  return floorActor;
}

// An emitter: the pass lights the scene with `emission`; VTK draws the surface unlit at that
// radiance (its ambient colour), so that both see the same surface.
void MakeEmitter(vtkActor* actor, const Vec3& emission)
{
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  actor->GetProperty()->SetAmbientColor(emission[0], emission[1], emission[2]);
  vtkVoxelGIPass::SetPropEmission(actor, emission[0], emission[1], emission[2]);
}

// MakeHomogeneousVolume over the box [lo, hi], added to `renderer` (which owns it).
vtkVolume* AddHomogeneousVolume(
  vtkRenderer* renderer, const Vec3& lo, const Vec3& hi, double alpha, const Vec3& color)
{
  const double bounds[6] = { lo[0], hi[0], lo[1], hi[1], lo[2], hi[2] };
  vtkSmartPointer<vtkVolume> volume =
    vtkVoxelGIScenes::MakeHomogeneousVolume(bounds, alpha, color.data());
  renderer->AddVolume(volume);
  return volume;
}

// A point light of VTK's default attenuation (none) at `position`; the renderer owns it.
vtkLight* AddPointLight(
  vtkRenderer* renderer, const Vec3& position, const Vec3& color, double intensity)
{
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetPosition(position[0], position[1], position[2]);
  light->SetFocalPoint(position[0], position[1] - 1.0, position[2]);
  light->SetConeAngle(90.0);
  light->SetColor(color[0], color[1], color[2]);
  light->SetIntensity(intensity);
  renderer->AddLight(light);
  return light;
}

// A box of the given bounds.
vtkActor* AddBox(vtkRenderer* renderer, const Vec3& lo, const Vec3& hi, const Vec3& color)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]);
  return vtkVoxelGIScenes::AddSource(renderer, cube, color[0], color[1], color[2]);
}

// AddRoom's five faces and the front wall behind the camera: a room closed on every side.
vtkActor* AddClosedRoom(vtkRenderer* renderer, const Vec3& lo, const Vec3& hi, const Vec3& floor,
  const Vec3& walls, const Vec3& left, const Vec3& right)
{
  vtkActor* floorActor = AddRoom(renderer, lo, hi, floor, walls, left, right);
  AddQuad(renderer, { lo[0], lo[1], hi[2] }, { lo[0], hi[1], hi[2] }, { hi[0], lo[1], hi[2] },
    walls);
  renderer->AutomaticLightCreationOff();
  return floorActor;
}

vtkActor* AddSphere(vtkRenderer* renderer, const Vec3& centre, double radius, const Vec3& color)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(centre[0], centre[1], centre[2]);
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(32);
  return vtkVoxelGIScenes::AddSource(renderer, sphere, color[0], color[1], color[2]);
}

// VTK's wavelet contoured at RTData = 157 (over [-10, 10]^3), placed by `place` (none: as it
// is), coloured by height from `low` to `high` (world y) through a blue-to-red lookup table.
void AddWaveletIsosurface(vtkRenderer* renderer, vtkTransform* place, double low, double high)
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  vtkNew<vtkContourFilter> contour;
  contour->SetInputConnection(wavelet->GetOutputPort());
  contour->SetValue(0, 157.0);
  contour->ComputeScalarsOff();
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputConnection(contour->GetOutputPort());
  moved->SetTransform(place);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(place ? moved->GetOutputPort() : contour->GetOutputPort());
  elevation->SetLowPoint(0.0, low, 0.0);
  elevation->SetHighPoint(0.0, high, 0.0);
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->SetTableRange(0.0, 1.0);
  vtkActor* surface = vtkVoxelGIScenes::AddSource(renderer, elevation, 1.0, 1.0, 1.0);
  vtkPolyDataMapper* mapper = vtkPolyDataMapper::SafeDownCast(surface->GetMapper());
  mapper->SetLookupTable(lut);
  mapper->SetScalarRange(0.0, 1.0);
  mapper->ScalarVisibilityOn();
}

void AimCamera(
  vtkRenderer* renderer, const Vec3& position, const Vec3& focalPoint, double viewAngle = 30.0)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(focalPoint[0], focalPoint[1], focalPoint[2]);
  camera->SetPosition(position[0], position[1], position[2]);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(viewAngle);
  renderer->ResetCameraClippingRange();
}
}

vtkSmartPointer<vtkVolume> vtkVoxelGIScenes::MakeHomogeneousVolume(
  const double bounds[6], double alpha, const double color[3])
{
  // Points at most 0.1 apart (up to 257 a side): VTK's ray caster gives a ray that leaves a
  // two-point image through its side the opacity of one crossing its whole depth.
  int dimensions[3];
  double spacing[3];
  for (int i = 0; i < 3; ++i)
  {
    const double extent = bounds[2 * i + 1] - bounds[2 * i];
    dimensions[i] = 1 + static_cast<int>(std::min(256.0, std::max(1.0, std::ceil(extent / 0.1))));
    spacing[i] = extent / (dimensions[i] - 1);
  }
  vtkNew<vtkImageData> box;
  box->SetDimensions(dimensions);
  box->SetOrigin(bounds[0], bounds[2], bounds[4]);
  box->SetSpacing(spacing);
  box->AllocateScalars(VTK_FLOAT, 1);
  static_cast<vtkFloatArray*>(box->GetPointData()->GetScalars())->FillValue(1.f);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, alpha);
  opacity->AddPoint(2.0, alpha);
  vtkNew<vtkColorTransferFunction> colors;
  colors->AddRGBPoint(0.0, color[0], color[1], color[2]);
  colors->AddRGBPoint(2.0, color[0], color[1], color[2]);
  // The OpenGL ray caster itself: no object factory needed to make it.
  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> mapper;
  mapper->SetInputData(box);
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  volume->GetProperty()->SetScalarOpacity(opacity);
  volume->GetProperty()->SetColor(colors);
  volume->GetProperty()->SetScalarOpacityUnitDistance(1.0);
  volume->GetProperty()->SetInterpolationTypeToLinear();
  return volume;
}

vtkActor* vtkVoxelGIScenes::AddSource(
  vtkRenderer* renderer, vtkAlgorithm* source, double r, double g, double b)
{
  if (!renderer || !source)
  {
    return nullptr;
  }
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  renderer->AddActor(actor);
  return actor;
}

void vtkVoxelGIScenes::AddCornellBox(vtkRenderer* renderer, double panelEmission)
{
  if (!renderer)
  {
    return;
  }
  const Vec3 white{ { 0.75, 0.75, 0.75 } };
  const Vec3 red{ { 0.75, 0.1, 0.1 } };
  const Vec3 green{ { 0.1, 0.6, 0.1 } };
  const double S = Size;

  AddRoom(renderer, { 0, 0, 0 }, { S, S, S }, white, white, red, green);
  AddBlock(renderer, 3.7, 2.0, 1.65, 1.65, 1.65, -17.0, white);
  AddBlock(renderer, 1.9, 3.4, 1.65, 3.3, 1.65, 15.0, white);

  // Emissive ceiling panel, a little below the ceiling, facing down.
  const double a = 0.38 * S, b = 0.62 * S, y = S - 0.01;
  MakeEmitter(AddQuad(renderer, { a, y, a }, { b, y, a }, { a, y, b }, { 1.0, 1.0, 1.0 }),
    { panelEmission, panelEmission, 0.85 * panelEmission });

  AddPointLight(renderer, { 0.5 * S, S - 0.3, 0.5 * S }, { 1.0, 0.95, 0.85 }, 1.0);
  AimCamera(renderer, { 0.5 * S, 0.5 * S, 2.9 * S }, { 0.5 * S, 0.5 * S, 0.5 * S });
}

void vtkVoxelGIScenes::AddGlossyRoom(vtkRenderer* renderer)
{
  if (!renderer)
  {
    return;
  }
  const double S = 6.0;
  // The floor is glossy: Blinn-Phong of power 60 over a dark diffuse base.
  vtkProperty* floor = AddRoom(renderer, { 0, 0, 0 }, { S, S, S }, { 0.3, 0.3, 0.32 },
    { 0.75, 0.75, 0.75 }, { 0.15, 0.25, 0.7 }, { 0.75, 0.5, 0.15 })
                         ->GetProperty();
  floor->SetSpecular(0.6);
  floor->SetSpecularColor(1.0, 1.0, 1.0);
  floor->SetSpecularPower(60.0);

  // A bright strip on the back wall, just in front of it, and a dimmer warm square on the left.
  MakeEmitter(AddQuad(renderer, { 1.2, 3.6, 0.01 }, { 4.8, 3.6, 0.01 }, { 1.2, 4.4, 0.01 },
                { 1.0, 1.0, 1.0 }),
    { 6.0, 6.0, 6.0 });
  MakeEmitter(AddQuad(renderer, { 0.01, 1.0, 1.5 }, { 0.01, 2.0, 1.5 }, { 0.01, 1.0, 2.5 },
                { 1.0, 1.0, 1.0 }),
    { 3.0, 1.5, 0.5 });

  AddSphere(renderer, { 2.0, 0.9, 3.0 }, 0.9, { 0.8, 0.8, 0.8 });
  AddBlock(renderer, 4.3, 2.2, 1.2, 1.6, 1.2, 25.0, { 0.7, 0.2, 0.2 });

  // A dim fill light behind the camera: its highlight on the floor is out of view.
  AddPointLight(renderer, { 0.5 * S, 5.5, 3.5 * S }, { 1.0, 1.0, 1.0 }, 0.3);
  AimCamera(renderer, { 0.5 * S, 0.5 * S, 2.9 * S }, { 0.5 * S, 0.5 * S, 0.5 * S });
}

void vtkVoxelGIScenes::AddIsosurfaceRoom(vtkRenderer* renderer)
{
  if (!renderer)
  {
    return;
  }
  // The wavelet's isosurface, coloured by height, in a room.
  AddWaveletIsosurface(renderer, nullptr, -10.0, 10.0);

  AddRoom(renderer, { -16, -11, -16 }, { 16, 19, 16 }, { 0.75, 0.75, 0.75 },
    { 0.75, 0.75, 0.75 }, { 0.7, 0.7, 0.3 }, { 0.3, 0.6, 0.7 });
  AddPointLight(renderer, { 0.0, 17.0, 4.0 }, { 1.0, 1.0, 1.0 }, 1.0);
  AimCamera(renderer, { 0.0, 4.0, 62.0 }, { 0.0, 3.0, 0.0 });
}

void vtkVoxelGIScenes::AddGlyphField(vtkRenderer* renderer)
{
  if (!renderer)
  {
    return;
  }
  // A sky of radiance 0.3: the background, and every surface's ambient term (ambient
  // coefficient 0.3 of its own colour) is what that sky would reflect unoccluded.
  const double sky = 0.3;
  renderer->SetBackground(sky, sky, sky);

  vtkActor* ground =
    AddQuad(renderer, { -12, 0, -12 }, { -12, 0, 12 }, { 12, 0, -12 }, { 0.7, 0.7, 0.7 });

  // 9 x 9 boxes on a 2-unit grid, their heights from a smooth bump function.
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> sizes;
  sizes->SetNumberOfComponents(3);
  for (int i = 0; i < 9; ++i)
  {
    for (int k = 0; k < 9; ++k)
    {
      const double x = 2.0 * (i - 4), z = 2.0 * (k - 4);
      points->InsertNextPoint(x, 0.0, z);
      const double h = 0.6 + 2.4 * (0.5 + 0.5 * std::sin(0.7 * x) * std::cos(0.5 * z));
      sizes->InsertNextTuple3(1.3, h, 1.3);
    }
  }
  vtkNew<vtkPolyData> centres;
  centres->SetPoints(points);
  centres->GetPointData()->SetVectors(sizes);
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(0.0, 0.5, 0.0);
  vtkNew<vtkGlyph3D> glyphs;
  glyphs->SetInputData(centres);
  glyphs->SetSourceConnection(cube->GetOutputPort());
  glyphs->SetScaleModeToScaleByVectorComponents();
  glyphs->OrientOff();
  vtkActor* boxes = AddSource(renderer, glyphs, 0.85, 0.6, 0.35);
  boxes->GetMapper()->ScalarVisibilityOff();
  ground->GetProperty()->SetAmbient(sky);
  boxes->GetProperty()->SetAmbient(sky);

  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(-5.0, 10.0, 4.0);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  sun->SetColor(1.0, 0.97, 0.9);
  sun->SetIntensity(1.0);
  renderer->AddLight(sun);
  AimCamera(renderer, { 15.0, 13.0, 23.0 }, { 0.0, 0.5, 0.0 });
}

void vtkVoxelGIScenes::AddEmissiveBox(vtkRenderer* renderer)
{
  if (!renderer)
  {
    return;
  }
  // Closed: the room's five faces and a front wall behind the camera. No vtkLight at all (and
  // no headlight): the ceiling panel's emission is the only light.
  const double S = 5.0;
  const Vec3 white{ { 0.75, 0.75, 0.75 } };
  AddRoom(renderer, { 0, 0, 0 }, { S, S, S }, white, white, { 0.75, 0.7, 0.2 },
    { 0.2, 0.3, 0.75 });
  AddQuad(renderer, { 0, 0, S }, { 0, S, S }, { S, 0, S }, white);
  const double a = 0.5 * S - 1.0, b = 0.5 * S + 1.0, y = S - 0.01;
  MakeEmitter(AddQuad(renderer, { a, y, a }, { b, y, a }, { a, y, b }, { 1.0, 1.0, 1.0 }),
    { 10.0, 10.0, 10.0 });
  AddBlock(renderer, 3.5, 1.6, 1.3, 1.6, 1.3, 20.0, white);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(1.5, 0.8, 1.9);
  sphere->SetRadius(0.8);
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(24);
  AddSource(renderer, sphere, 0.75, 0.75, 0.75);
  renderer->AutomaticLightCreationOff();
  AimCamera(renderer, { 0.5 * S, 0.6 * S, 0.97 * S }, { 0.5 * S, 0.28 * S, 0.0 }, 60.0);
}

void vtkVoxelGIScenes::AddStreamlines(vtkRenderer* renderer)
{
  if (!renderer)
  {
    return;
  }
  // A vortex about the vertical axis that rises and is pulled inward: (-z, 0.4, x) - 0.15 (x,
  // 0, z), sampled on a 25^3 grid over [-6, 6]^3.
  const int n = 25;
  const double h = 12.0 / (n - 1);
  vtkNew<vtkImageData> field;
  field->SetDimensions(n, n, n);
  field->SetOrigin(-6.0, -6.0, -6.0);
  field->SetSpacing(h, h, h);
  vtkNew<vtkDoubleArray> velocity;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const double x = -6.0 + h * i, z = -6.0 + h * k;
        velocity->SetTuple3(i + n * (j + n * k), -z - 0.15 * x, 0.4, x - 0.15 * z);
      }
    }
  }
  field->GetPointData()->SetVectors(velocity);
  vtkNew<vtkLineSource> seeds;
  seeds->SetPoint1(1.5, -5.5, 0.0);
  seeds->SetPoint2(5.5, -5.5, 0.0);
  seeds->SetResolution(9);
  vtkNew<vtkStreamTracer> tracer;
  tracer->SetInputData(field);
  tracer->SetSourceConnection(seeds->GetOutputPort());
  tracer->SetIntegrationDirectionToForward();
  tracer->SetMaximumPropagation(60.0);
  tracer->SetInitialIntegrationStep(0.2);
  vtkNew<vtkTubeFilter> tubes;
  tubes->SetInputConnection(tracer->GetOutputPort());
  tubes->SetRadius(0.15);
  tubes->SetNumberOfSides(12);
  tubes->CappingOn();
  // Triangles instead of the tubes' strips: the scene description (OBJ) keeps only polygons.
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(tubes->GetOutputPort());
  vtkNew<vtkAssignAttribute> time;
  time->SetInputConnection(triangles->GetOutputPort());
  time->Assign("IntegrationTime", vtkDataSetAttributes::SCALARS, vtkAssignAttribute::POINT_DATA);
  time->Update();
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.6, 0.0);
  lut->SetTableRange(
    vtkPolyData::SafeDownCast(time->GetOutput())->GetPointData()->GetScalars()->GetRange());
  vtkActor* actor = AddSource(renderer, time, 1.0, 1.0, 1.0);
  vtkPolyDataMapper* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
  mapper->SetLookupTable(lut);
  mapper->UseLookupTableScalarRangeOn();
  mapper->ScalarVisibilityOn();

  AddQuad(renderer, { -9, -6.2, -9 }, { -9, -6.2, 9 }, { 9, -6.2, -9 }, { 0.7, 0.7, 0.7 });
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(-4.0, 10.0, 6.0);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  sun->SetIntensity(0.8);
  renderer->AddLight(sun);
  AddPointLight(renderer, { 0.0, 3.0, 0.0 }, { 1.0, 0.9, 0.8 }, 0.4);
  AimCamera(renderer, { 14.0, 9.0, 26.0 }, { 0.0, -1.0, 0.0 });
}

void vtkVoxelGIScenes::AddVolumeSlab(vtkRenderer* renderer)
{
  if (!renderer)
  {
    return;
  }
  const double sky = 0.3; // as the glyph field's: the ambient terms are the sky's light
  renderer->SetBackground(sky, sky, sky);
  std::vector<vtkActor*> actors;
  actors.push_back(
    AddQuad(renderer, { -8, 0, -8 }, { -8, 0, 8 }, { 8, 0, -8 }, { 0.7, 0.7, 0.7 }));
  vtkNew<vtkCubeSource> box;
  box->SetBounds(-3.5, -1.5, 0.0, 2.0, -1.0, 1.0);
  actors.push_back(AddSource(renderer, box, 0.3, 0.5, 0.9));
  vtkNew<vtkSphereSource> ball;
  ball->SetCenter(2.0, 1.2, 1.5);
  ball->SetRadius(1.2);
  ball->SetThetaResolution(48);
  ball->SetPhiResolution(48);
  actors.push_back(AddSource(renderer, ball, 0.9, 0.5, 0.2));
  for (vtkActor* actor : actors)
  {
    actor->GetProperty()->SetAmbient(sky);
  }

  // The slab: black, opacity 0.6 per unit.
  AddHomogeneousVolume(renderer, { -4.0, 3.5, -3.0 }, { 4.0, 4.5, 3.0 }, 0.6, { 0, 0, 0 });

  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(-6.0, 8.0, -5.0);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  sun->SetIntensity(1.0);
  renderer->AddLight(sun);
  AimCamera(renderer, { 10.0, 11.0, 15.0 }, { 0.0, 1.0, 0.0 });
}

void vtkVoxelGIScenes::AddPointLightRoom(vtkRenderer* renderer)
{
  if (!renderer)
  {
    return;
  }
  const Vec3 white{ { 0.7, 0.7, 0.7 } };
  AddClosedRoom(renderer, { 0, 0, 0 }, { 10, 6, 10 }, { 0.4, 0.4, 0.4 }, white,
    { 0.7, 0.12, 0.1 }, white);
  AddBlock(renderer, 5.5, 4.0, 2.4, 1.0, 1.6, 0.0, { 0.55, 0.4, 0.25 });
  // The wavelet's isosurface, coloured by height through a lookup table, resting on the table.
  vtkNew<vtkTransform> place;
  place->Translate(5.5, 1.0 + 0.06 * 10.0, 4.0);
  place->Scale(0.06, 0.06, 0.06);
  AddWaveletIsosurface(renderer, place, 1.0, 2.2);

  AddPointLight(renderer, { 5.0, 5.2, 5.0 }, { 1.0, 0.95, 0.85 }, 18.0)
    ->SetAttenuationValues(0.0, 0.0, 1.0);
  AimCamera(renderer, { 5.0, 3.2, 9.6 }, { 4.0, 2.0, 0.0 }, 60.0);
}

void vtkVoxelGIScenes::AddLampRoom(vtkRenderer* renderer)
{
  if (!renderer)
  {
    return;
  }
  const Vec3 grey{ { 0.5, 0.5, 0.5 } };
  AddClosedRoom(
    renderer, { 0, 0, 0 }, { 4, 2.6, 5 }, { 0.55, 0.45, 0.35 }, grey, { 0.15, 0.25, 0.6 }, grey);
  AddSphere(renderer, { 1.2, 0.5, 2.0 }, 0.5, { 0.7, 0.7, 0.7 });
  AddBlock(renderer, 2.9, 1.5, 0.8, 1.2, 0.8, 30.0, { 0.8, 0.45, 0.15 });
  AddPointLight(renderer, { 2.0, 2.3, 2.2 }, { 1.0, 0.95, 0.85 }, 0.5);
  AimCamera(renderer, { 2.0, 1.4, 4.9 }, { 2.0, 0.9, 0.0 }, 60.0);
}

void vtkVoxelGIScenes::AddEmitterRoom(vtkRenderer* renderer)
{
  if (!renderer)
  {
    return;
  }
  const Vec3 white{ { 0.75, 0.75, 0.75 } };
  AddClosedRoom(
    renderer, { 0, 0, 0 }, { 5, 3, 6 }, { 0.6, 0.6, 0.6 }, white, white, { 0.2, 0.55, 0.2 });
  // No vtkLight: a small emissive cube hanging in the room is the only light.
  MakeEmitter(AddBox(renderer, { 2.35, 1.85, 2.85 }, { 2.65, 2.15, 3.15 }, white),
    { 20.0, 18.0, 15.0 });
  AddBlock(renderer, 1.2, 1.5, 1.0, 1.4, 1.0, -15.0, white);
  AddSphere(renderer, { 3.6, 0.6, 2.5 }, 0.6, { 0.75, 0.6, 0.4 });
  AimCamera(renderer, { 2.5, 1.6, 5.9 }, { 2.5, 1.0, 0.0 }, 60.0);
}

void vtkVoxelGIScenes::AddVolumeRoom(vtkRenderer* renderer)
{
  if (!renderer)
  {
    return;
  }
  // Closed and white; no vtkLight: a ceiling panel's emission is the only light, so the
  // orange volume shows, over the colour VTK gives it unlit, the room's light it scatters.
  const Vec3 white{ { 0.75, 0.75, 0.75 } };
  AddClosedRoom(renderer, { 0, 0, 0 }, { 5, 4, 5 }, white, white, white, white);
  MakeEmitter(AddQuad(renderer, { 1.5, 3.99, 1.5 }, { 3.5, 3.99, 1.5 }, { 1.5, 3.99, 3.5 },
                { 1.0, 1.0, 1.0 }),
    { 5.0, 5.0, 5.0 });
  AddHomogeneousVolume(renderer, { 0.9, 0.7, 1.2 }, { 3.1, 2.3, 3.0 }, 0.5, { 0.9, 0.55, 0.25 });
  AddSphere(renderer, { 4.0, 0.6, 1.5 }, 0.6, white);
  renderer->AutomaticLightCreationOff();
  AimCamera(renderer, { 2.5, 2.6, 4.9 }, { 2.3, 1.0, 0.0 }, 60.0);
}

void vtkVoxelGIScenes::AddContacts(vtkRenderer* renderer, bool headlight)
{
  if (!renderer)
  {
    return;
  }
  const Vec3 grey{ { 0.7, 0.7, 0.7 } };
  AddQuad(renderer, { -6, 0, -3 }, { -6, 0, 6 }, { 6, 0, -3 }, grey);
  AddQuad(renderer, { -6, 0, -3 }, { 6, 0, -3 }, { -6, 5, -3 }, grey);
  // A heat sink: eight thin fins on a base plate, gaps of two fin widths.
  const Vec3 metal{ { 0.75, 0.75, 0.78 } };
  AddBox(renderer, { -4.4, 0.0, -0.8 }, { -2.2, 0.3, 0.8 }, metal);
  for (int i = 0; i < 8; ++i)
  {
    const double x = -4.35 + 0.28 * i;
    AddBox(renderer, { x, 0.3, -0.8 }, { x + 0.09, 1.5, 0.8 }, metal);
  }
  // Three spheres touching each other and the floor.
  for (int i = 0; i < 3; ++i)
  {
    AddSphere(renderer, { -0.6 + 1.2 * i, 0.6, 0.6 }, 0.6, { 0.8, 0.45, 0.2 });
  }
  // A column standing against the wall.
  vtkNew<vtkCylinderSource> column;
  column->SetCenter(3.6, 1.0, -2.6);
  column->SetRadius(0.4);
  column->SetHeight(2.0);
  column->SetResolution(48);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(column->GetOutputPort());
  AddSource(renderer, triangles, 0.3, 0.45, 0.8);
  AddBlock(renderer, 2.0, 2.5, 0.9, 0.9, 0.9, 35.0, grey);
  if (!headlight)
  {
    AddPointLight(renderer, { -2.0, 6.0, 5.0 }, { 1.0, 1.0, 1.0 }, 0.9);
  }
  AimCamera(renderer, { 0.0, 5.0, 11.5 }, { -0.3, 0.8, -0.5 }, 42.0);
}

void vtkVoxelGIScenes::AddTranslucentSurfaces(vtkRenderer* renderer)
{
  if (!renderer)
  {
    return;
  }
  const Vec3 grey{ { 0.7, 0.7, 0.7 } };
  AddQuad(renderer, { -6, 0, -3 }, { -6, 0, 6 }, { 6, 0, -3 }, grey);
  AddQuad(renderer, { -6, 0, -3 }, { 6, 0, -3 }, { -6, 5, -3 }, grey);
  // A blue glass canopy over a white block, an orange glass ball, an opaque red ball.
  AddQuad(renderer, { -4.5, 2.4, -2.5 }, { -4.5, 2.4, 1.5 }, { -0.8, 2.4, -2.5 },
    { 0.2, 0.5, 0.9 })
    ->GetProperty()
    ->SetOpacity(0.5);
  AddBlock(renderer, -2.4, -0.6, 1.0, 1.0, 1.0, 20.0, { 0.85, 0.85, 0.85 });
  AddSphere(renderer, { 1.6, 1.0, 0.2 }, 1.0, { 0.95, 0.55, 0.1 })->GetProperty()->SetOpacity(0.4);
  AddSphere(renderer, { 3.9, 0.6, -1.6 }, 0.6, { 0.8, 0.2, 0.15 });
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(-3.0, 8.0, 5.0);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(sun);
  AimCamera(renderer, { 0.0, 5.0, 11.5 }, { -0.3, 0.8, -0.5 }, 42.0);
}

bool vtkVoxelGIScenes::AddScene(vtkRenderer* renderer, const char* name)
{
  if (!renderer || !name)
  {
    return false;
  }
  if (!std::strcmp(name, "cornell"))
  {
    AddCornellBox(renderer);
  }
  else if (!std::strcmp(name, "glossy"))
  {
    AddGlossyRoom(renderer);
  }
  else if (!std::strcmp(name, "isosurface"))
  {
    AddIsosurfaceRoom(renderer);
  }
  else if (!std::strcmp(name, "glyphs"))
  {
    AddGlyphField(renderer);
  }
  else if (!std::strcmp(name, "emissive"))
  {
    AddEmissiveBox(renderer);
  }
  else if (!std::strcmp(name, "streamlines"))
  {
    AddStreamlines(renderer);
  }
  else if (!std::strcmp(name, "volume"))
  {
    AddVolumeSlab(renderer);
  }
  else if (!std::strcmp(name, "pointroom"))
  {
    AddPointLightRoom(renderer);
  }
  else if (!std::strcmp(name, "lamproom"))
  {
    AddLampRoom(renderer);
  }
  else if (!std::strcmp(name, "emitterroom"))
  {
    AddEmitterRoom(renderer);
  }
  else if (!std::strcmp(name, "volumeroom"))
  {
    AddVolumeRoom(renderer);
  }
  else if (!std::strcmp(name, "contacts"))
  {
    AddContacts(renderer, false);
  }
  else if (!std::strcmp(name, "contactsheadlight"))
  {
    AddContacts(renderer, true);
  }
  else if (!std::strcmp(name, "translucent"))
  {
    AddTranslucentSurfaces(renderer);
  }
  else
  {
    return false;
  }
  return true;
}

bool vtkVoxelGIScenes::DrawsOverComposite(vtkRenderer* renderer)
{
  if (renderer->GetVolumes()->GetNumberOfItems() > 0)
  {
    return true;
  }
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    if (actor->GetVisibility() && !actor->HasOpaqueGeometry())
    {
      return true;
    }
  }
  return false;
}

void vtkVoxelGIScenes::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
