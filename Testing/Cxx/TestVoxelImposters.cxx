// Shapes VTK draws as sprites against the same shapes as polygons, over a floor under a sun:
// points drawn as spheres (RenderPointsAsSpheres: a cloud of 150 points of 10 pixels) and
// lines drawn as tubes (RenderLinesAsTubes: nine lines of 10 pixels) against spheres glyphed
// and tubes swept of the radius the imposters show (half the point size or line width in
// pixels at the shapes' centre's distance from the camera: VTK's imposters are that many
// pixels across); the same cloud as a vtkPointGaussianMapper's sphere splats (a splat shape
// that keeps the splat's radius, of 0.2 and, through a scale array and function, 0.1-0.3)
// against spheres of those radii; and 60 carbon atoms drawn by a vtkMoleculeMapper (no bonds)
// against spheres of carbon's van der Waals radius times the mapper's default 0.3
// (vtkPeriodicTable). Their voxel occupancy above the floor and the ambient occlusion of the
// floor below them agree within 5 %. Bonds: two oxygen atoms 3 apart, bonded, leave the voxel
// between them empty without bonds and fill it, in oxygen's colour of the periodic table, with
// them; the atoms' voxels have that colour too.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3D.h"
#include "vtkTubeFilter.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkMolecule.h"
#include "vtkMoleculeMapper.h"
#include "vtkNew.h"
#include "vtkPeriodicTable.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointGaussianMapper.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>

namespace
{
using glm::dvec3;
constexpr int Size = 200;
constexpr double PointSize = 10.0;
const dvec3 Eye(0.0, 6.0, 12.0), Centre(0.0, 2.0, 0.0);

struct Measured
{
  int Occupied = 0;     // voxels above the floor
  double FloorAO = 0.0; // mean AO of the floor's pixels below the cloud
};

/// 150 points in a ball of radius 1.5 around Centre (a fixed sequence).
vtkSmartPointer<vtkPolyData> Cloud()
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> verts;
  while (points->GetNumberOfPoints() < 150)
  {
    double p[3];
    for (double& c : p)
    {
      c = random->GetRangeValue(-1.5, 1.5);
      random->Next();
    }
    if (vtkMath::Norm(p) <= 1.5)
    {
      verts->InsertNextCell(1);
      verts->InsertCellPoint(points->InsertNextPoint(p[0], p[1] + Centre.y, p[2]));
    }
  }
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  cloud->SetVerts(verts);
  return cloud;
}

/// Nine lines along x, 3 long, on a 3 x 3 grid across y and z around Centre.
vtkSmartPointer<vtkPolyData> Lines()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (int j = -1; j <= 1; ++j)
  {
    for (int k = -1; k <= 1; ++k)
    {
      lines->InsertNextCell(10);
      for (int i = 0; i < 10; ++i)
      {
        lines->InsertCellPoint(points->InsertNextPoint(-1.5 + i / 3.0, Centre.y + j, k));
      }
    }
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->SetPoints(points);
  result->SetLines(lines);
  return result;
}

/// Render the actor `shape` makes over the floor under a sun: its voxels above the floor and
/// the AO of the floor below; the voxel albedo in `albedo`.
bool Measure(const std::function<vtkSmartPointer<vtkActor>()>& shape, Measured& m,
  vtkImageData* albedo)
{
  voxelgi_test::GIWindow view(nullptr, 64, Size, 0);
  vtkRenderer* renderer = view.Renderer;
  renderer->AutomaticLightCreationOff();
  voxelgi_test::AddQuad(renderer, { -6, 0, -6 }, { -6, 0, 6 }, { 6, 0, -6 }, 0.8, 0.8, 0.8);
  renderer->AddActor(shape());
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(-1.0, 10.0, 2.0);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(sun);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(Eye.x, Eye.y, Eye.z);
  camera->SetFocalPoint(Centre.x, Centre.y, Centre.z);
  camera->SetViewAngle(30.0);
  renderer->ResetCameraClippingRange();
  view.Window->Render();
  vtkNew<vtkFloatArray> indirect;
  if (!view.GI->GetGIActive() ||
    !view.GI->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, albedo) ||
    !view.GI->GetFloatImage(vtkVoxelGIPass::IMAGE_INDIRECT, indirect))
  {
    return false;
  }
  vtkDataArray* values = albedo->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    double p[3];
    albedo->GetPoint(i, p);
    m.Occupied += (p[1] > 0.3 && values->GetComponent(i, 3) > 0.0) ? 1 : 0;
  }
  // The floor below and in front of the shapes: the lower part of the image.
  m.FloorAO = voxelgi_test::MeanOver(indirect, Size, 40, 10, 160, 50, 3);
  return true;
}

vtkSmartPointer<vtkActor> ActorOf(vtkMapper* mapper)
{
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.9, 0.4, 0.2);
  return actor;
}

/// Points or lines (`tubes`) drawn as imposters of `PointSize` pixels.
vtkSmartPointer<vtkActor> Imposters(vtkPolyData* shapes, bool tubes)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(shapes);
  vtkSmartPointer<vtkActor> actor = ActorOf(mapper);
  actor->GetProperty()->SetRenderPointsAsSpheres(!tubes);
  actor->GetProperty()->SetRenderLinesAsTubes(tubes);
  actor->GetProperty()->SetPointSize(PointSize);
  actor->GetProperty()->SetLineWidth(PointSize);
  return actor;
}

/// Polygonal spheres glyphed at the points of `shapes`, of `radius` or, when `scales` names
/// an array, of its values; or polygonal tubes of `radius` swept along its lines (`tubes`).
vtkSmartPointer<vtkActor> Polygons(
  vtkPolyData* shapes, bool tubes, double radius, const char* scales = nullptr)
{
  vtkNew<vtkPolyDataMapper> mapper;
  if (tubes)
  {
    vtkNew<vtkTubeFilter> swept;
    swept->SetInputData(shapes);
    swept->SetRadius(radius);
    swept->SetNumberOfSides(16);
    swept->CappingOn();
    swept->Update();
    mapper->SetInputData(swept->GetOutput());
  }
  else
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetRadius(scales ? 1.0 : radius);
    sphere->SetThetaResolution(16);
    sphere->SetPhiResolution(12);
    vtkNew<vtkGlyph3D> glyphs;
    glyphs->SetInputData(shapes);
    glyphs->SetSourceConnection(sphere->GetOutputPort());
    glyphs->SetScaling(scales != nullptr);
    glyphs->SetScaleModeToScaleByScalar();
    glyphs->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, scales);
    glyphs->Update();
    mapper->SetInputData(glyphs->GetOutput());
  }
  return ActorOf(mapper);
}

/// The sprites' occupancy and floor AO against the polygons'.
bool Agree(const char* what, const std::function<vtkSmartPointer<vtkActor>()>& sprites,
  const std::function<vtkSmartPointer<vtkActor>()>& polygons)
{
  Measured a, b;
  vtkNew<vtkImageData> albedo;
  if (!Measure(sprites, a, albedo) || !Measure(polygons, b, albedo))
  {
    std::cerr << what << ": GI did not run" << std::endl;
    return false;
  }
  std::cout << what << ": occupied voxels " << a.Occupied << " against " << b.Occupied
            << " (polygons); floor AO " << a.FloorAO << " against " << b.FloorAO << std::endl;
  if (b.Occupied <= 100 || b.FloorAO <= 0.01)
  {
    std::cerr << what << ": nothing measured" << std::endl;
    return false;
  }
  bool ok = voxelgi_test::Within(std::string("occupancy of ") + what + " against polygons",
    std::abs(static_cast<double>(a.Occupied) / b.Occupied - 1.0), 0.05, 0.05);
  ok = voxelgi_test::Within(std::string("floor AO of ") + what + " against polygons",
         std::abs(a.FloorAO / b.FloorAO - 1.0), 0.05, 0.05) &&
    ok;
  return ok;
}

/// The imposters of `shapes` against the same shapes as polygons.
bool Compare(vtkPolyData* shapes, bool tubes)
{
  // The imposters' world radius: half their size in pixels, a pixel being the view's height
  // at the shapes' distance over the image's height.
  const double distance = glm::length(Eye - Centre);
  const double radius = 0.5 * PointSize *
    (2.0 * distance * std::tan(vtkMath::RadiansFromDegrees(15.0))) / Size;
  std::cout << "imposters of radius " << radius << std::endl;
  return Agree(tubes ? "imposter tubes" : "imposter spheres",
    [&] { return Imposters(shapes, tubes); }, [&] { return Polygons(shapes, tubes, radius); });
}

/// ParaView's sphere splat: discards what lies beyond the splat's radius, shades the rest.
const char* SphereSplat = "//VTK::Color::Impl\n"
                          "float dist = dot(offsetVCVSOutput.xy, offsetVCVSOutput.xy);\n"
                          "if (dist > 1.0) { discard; }\n";

/// The cloud as sphere splats of radius 0.2, then of 0.1 + 0.2 s (s a scale array in [0, 1],
/// through a scale function) against polygonal spheres of those radii.
bool CompareSplats()
{
  vtkSmartPointer<vtkPolyData> cloud = Cloud();
  vtkNew<vtkFloatArray> scales;
  scales->SetName("s");
  vtkNew<vtkFloatArray> radii; // what the splats' scale array and function give
  radii->SetName("r");
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
  {
    scales->InsertNextValue(static_cast<float>(i % 5) / 4.0f);
    radii->InsertNextValue(0.1f + 0.2f * scales->GetValue(i));
  }
  cloud->GetPointData()->AddArray(scales);
  cloud->GetPointData()->AddArray(radii);
  vtkNew<vtkPiecewiseFunction> function; // maps 0.25 s (the scale factor times s) to 0.1 + 0.2 s
  function->AddPoint(0.0, 0.1);
  function->AddPoint(0.25, 0.3);
  auto splats = [&](bool scaled) {
    vtkNew<vtkPointGaussianMapper> mapper;
    mapper->SetInputData(cloud);
    mapper->SetSplatShaderCode(SphereSplat);
    mapper->EmissiveOff();
    mapper->SetScaleFactor(scaled ? 0.25 : 0.2);
    if (scaled)
    {
      mapper->SetScaleArray("s");
      mapper->SetScaleFunction(function);
    }
    return ActorOf(mapper);
  };
  bool ok = Agree(
    "sphere splats", [&] { return splats(false); }, [&] { return Polygons(cloud, false, 0.2); });
  ok = Agree("sphere splats through a scale array", [&] { return splats(true); },
         [&] { return Polygons(cloud, false, 0.0, "r"); }) &&
    ok;
  return ok;
}

/// 60 carbon atoms at the cloud's first points, without bonds, against polygonal spheres.
bool CompareMolecule()
{
  vtkSmartPointer<vtkPolyData> cloud = Cloud();
  vtkNew<vtkPoints> points;
  vtkNew<vtkMolecule> molecule;
  for (vtkIdType i = 0; i < 60; ++i)
  {
    double p[3];
    cloud->GetPoint(i, p);
    points->InsertNextPoint(p);
    molecule->AppendAtom(6, p[0], p[1], p[2]);
  }
  vtkNew<vtkPolyData> centres;
  centres->SetPoints(points);
  vtkNew<vtkPeriodicTable> elements;
  const double radius = 0.3 * elements->GetVDWRadius(6);
  return Agree(
    "molecule's atoms",
    [&] {
      vtkNew<vtkMoleculeMapper> mapper;
      mapper->SetInputData(molecule);
      mapper->RenderBondsOff();
      return ActorOf(mapper);
    },
    [&] { return Polygons(centres, false, radius); });
}

/// The colour of the voxel at `p` (RGBA8 voxels) and its occupancy.
double VoxelAt(vtkImageData* albedo, double x, double y, double z, double colour[3])
{
  double p[3] = { x, y, z };
  vtkDataArray* values = albedo->GetPointData()->GetScalars();
  const vtkIdType v = albedo->FindPoint(p);
  for (int c = 0; c < 3; ++c)
  {
    colour[c] = values->GetComponent(v, c) / 255.0;
  }
  return values->GetComponent(v, 3) / 255.0;
}

/// Two bonded oxygen atoms: the voxel between them is empty without bonds and oxygen-red
/// with them; the atoms' top voxels are oxygen-red.
bool CompareBonds()
{
  vtkNew<vtkMolecule> molecule;
  vtkAtom a = molecule->AppendAtom(8, -1.5, Centre.y, 0.0);
  vtkAtom b = molecule->AppendAtom(8, 1.5, Centre.y, 0.0);
  molecule->AppendBond(a, b, 1);
  vtkNew<vtkPeriodicTable> elements;
  float red[3];
  elements->GetDefaultRGBTuple(8, red);
  bool ok = true;
  for (bool bonds : { false, true })
  {
    Measured m;
    vtkNew<vtkImageData> albedo;
    auto bonded = [&] {
      vtkNew<vtkMoleculeMapper> mapper;
      mapper->SetInputData(molecule);
      mapper->SetAtomicRadiusTypeToUnitRadius();
      mapper->SetAtomicRadiusScaleFactor(0.4);
      mapper->SetBondRadius(0.3);
      mapper->SetRenderBonds(bonds);
      return ActorOf(mapper);
    };
    if (!Measure(bonded, m, albedo))
    {
      std::cerr << "bonds: GI did not run" << std::endl;
      return false;
    }
    double between[3], atom[3];
    const double occupancy = VoxelAt(albedo, 0.0, Centre.y, 0.0, between);
    const double atomOccupancy = VoxelAt(albedo, -1.5, Centre.y + 0.38, 0.0, atom);
    std::cout << "bonds " << (bonds ? "on" : "off") << ": the voxel between the atoms has "
              << "occupancy " << occupancy << ", albedo " << between[0] << " " << between[1]
              << " " << between[2] << "; an atom's top voxel " << atomOccupancy << ", "
              << atom[0] << " " << atom[1] << " " << atom[2] << " (oxygen " << red[0] << " "
              << red[1] << " " << red[2] << ")" << std::endl;
    ok = ok && (bonds ? occupancy > 0.0 : occupancy == 0.0) && atomOccupancy > 0.0;
    for (int c = 0; c < 3; ++c)
    {
      ok = ok && (!bonds || std::abs(between[c] - red[c]) < 0.02) &&
        std::abs(atom[c] - red[c]) < 0.02;
    }
  }
  if (!ok)
  {
    std::cerr << "FAILED: atoms and bonds are not voxelized where they are in their colour"
              << std::endl;
  }
  return ok;
}
}

int TestVoxelImposters(int, char*[])
{
  const bool spheres = Compare(Cloud(), false);
  const bool tubes = Compare(Lines(), true);
  const bool splats = CompareSplats();
  const bool molecule = CompareMolecule();
  const bool bonds = CompareBonds();
  return spheres && tubes && splats && molecule && bonds ? EXIT_SUCCESS : EXIT_FAILURE;
}
