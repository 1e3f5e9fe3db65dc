#include "ImposterProxies.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3D.h"
#include "vtkGlyph3DMapper.h"
#include "vtkLookupTable.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMolecule.h"
#include "vtkMoleculeMapper.h"
#include "vtkNew.h"
#include "vtkPeriodicTable.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPointGaussianMapper.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTubeFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>

namespace voxelgi
{

bool ImposterProxies::Applies(vtkActor* actor)
{
  return Splats(actor) || Molecule(actor) || Spheres(actor) || Tubes(actor);
}

bool ImposterProxies::Splats(vtkActor* actor)
{
  auto* mapper = vtkPointGaussianMapper::SafeDownCast(actor->GetMapper());
  // Without a shape, VTK's default splat is a translucent Gaussian blob: no surface.
  // ParaView's Point Gaussian representation gives its mapper a composite dataset.
  vtkDataObject* input = mapper ? mapper->GetInputDataObject(0, 0) : nullptr;
  return mapper && mapper->GetSplatShaderCode() && mapper->GetScaleFactor() > 0.0 &&
    (vtkPolyData::SafeDownCast(input) || vtkCompositeDataSet::SafeDownCast(input));
}

bool ImposterProxies::Molecule(vtkActor* actor)
{
  auto* mapper = vtkMoleculeMapper::SafeDownCast(actor->GetMapper());
  return mapper && mapper->GetInput();
}

vtkPolyData* ImposterProxies::Input(vtkActor* actor)
{
  vtkMapper* mapper = actor->GetMapper();
  return mapper && !mapper->IsA("vtkGlyph3DMapper")
    ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0))
    : nullptr;
}

bool ImposterProxies::Spheres(vtkActor* actor)
{
  // The property first: reading the input asks the mapper's pipeline, in every frame's scan.
  vtkProperty* property = actor->GetProperty();
  vtkPolyData* input = property->GetRenderPointsAsSpheres() ? Input(actor) : nullptr;
  if (!input)
  {
    return false;
  }
  // Points representation: every point; surface representation: its vertex cells, when it
  // has nothing else (lines and polygons keep their own notice or path).
  return property->GetRepresentation() == VTK_POINTS ||
    (property->GetRepresentation() == VTK_SURFACE && input->GetNumberOfVerts() > 0 &&
      input->GetNumberOfLines() + input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0);
}

bool ImposterProxies::Tubes(vtkActor* actor)
{
  vtkProperty* property = actor->GetProperty();
  const bool tubes =
    property->GetRenderLinesAsTubes() && property->GetRepresentation() != VTK_POINTS;
  vtkPolyData* input = tubes ? Input(actor) : nullptr;
  // Lines with nothing of area beside them (a surface's edges keep the surface's path).
  return input && input->GetNumberOfLines() > 0 &&
    input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0;
}

double ImposterProxies::WorldRadius(vtkActor* actor, vtkRenderer* renderer)
{
  const int* size = renderer->GetSize();
  const double height = size && size[1] > 0 ? size[1] : 300.0;
  vtkCamera* camera = renderer->GetActiveCamera();
  double centre[3];
  const double* b = actor->GetBounds();
  for (int i = 0; i < 3; ++i)
  {
    centre[i] = vtkMath::AreBoundsInitialized(b) ? 0.5 * (b[2 * i] + b[2 * i + 1]) : 0.0;
  }
  const double distance = std::sqrt(vtkMath::Distance2BetweenPoints(camera->GetPosition(), centre));
  const double viewHeight = camera->GetParallelProjection()
    ? 2.0 * camera->GetParallelScale()
    : 2.0 * distance * std::tan(vtkMath::RadiansFromDegrees(0.5 * camera->GetViewAngle()));
  vtkProperty* property = actor->GetProperty();
  const double pixels = Tubes(actor) ? property->GetLineWidth() : property->GetPointSize();
  return 0.5 * pixels * viewHeight / height;
}

vtkActor* ImposterProxies::Update(
  vtkActor* actor, vtkMTimeType signature, vtkRenderer* renderer, std::string& reason)
{
  auto* molecule = vtkMoleculeMapper::SafeDownCast(actor->GetMapper());
  vtkDataObject* input = molecule ? nullptr : actor->GetMapper()->GetInputDataObject(0, 0);
  const vtkIdType points = molecule ? molecule->GetInput()->GetNumberOfAtoms()
    : input                         ? input->GetNumberOfElements(vtkDataObject::POINT)
                                    : 0;
  if (points == 0)
  {
    reason = std::string(actor->GetClassName()) + " (" +
      (molecule         ? "a molecule"
          : Splats(actor) ? "splats"
          : Tubes(actor)  ? "lines drawn as tubes"
                          : "points drawn as spheres") +
      ", but no points)";
    this->Proxies.erase(actor);
    return nullptr;
  }
  // Splats and molecules have world radii; sprites of a size in pixels follow the zoom.
  const bool pixelSized = Spheres(actor) || Tubes(actor);
  const double radius = pixelSized ? WorldRadius(actor, renderer) : 0.0;
  Proxy& proxy = this->Proxies[actor];
  const bool zoomed =
    pixelSized && !(radius > 0.75 * proxy.Radius && radius < 1.25 * proxy.Radius);
  if (!proxy.Actor || proxy.Synced != signature || zoomed)
  {
    if (!proxy.Actor)
    {
      proxy.Actor = vtkSmartPointer<vtkActor>::New();
    }
    Build(actor, proxy.Actor, radius);
    proxy.Synced = signature;
    proxy.Radius = radius;
  }
  return proxy.Actor;
}

void ImposterProxies::Build(vtkActor* actor, vtkActor* proxy, double radius)
{
  proxy->SetMapper(Molecule(actor) ? MoleculeShapes(actor)
      : Splats(actor)              ? SplatShapes(actor)
      : Tubes(actor)               ? TubeShapes(actor, radius)
                                   : SphereShapes(actor, radius));
  proxy->GetProperty()->DeepCopy(actor->GetProperty());
  proxy->GetProperty()->SetRepresentationToSurface();
  proxy->GetProperty()->SetRenderPointsAsSpheres(false);
  proxy->GetProperty()->SetRenderLinesAsTubes(false);
  vtkNew<vtkMatrix4x4> matrix;
  matrix->DeepCopy(actor->GetMatrix());
  proxy->SetUserMatrix(matrix);
  proxy->Modified();
}

vtkSmartPointer<vtkMapper> ImposterProxies::TubeShapes(vtkActor* actor, double radius)
{
  // Each line as the cylinder its imposter shows, the lines' point data carried along.
  vtkNew<vtkTubeFilter> tubes;
  tubes->SetInputData(Input(actor));
  tubes->SetRadius(radius);
  tubes->SetNumberOfSides(8);
  tubes->CappingOn();
  auto polygons = vtkSmartPointer<vtkPolyDataMapper>::New();
  // The actor's colouring: lookup table, scalar mode and range, array selection.
  polygons->vtkMapper::ShallowCopy(actor->GetMapper());
  polygons->SetInputConnection(tubes->GetOutputPort());
  return polygons;
}

namespace
{
// The sphere every proxy glyphs: 12 x 8 facets, finer than the voxels of a sprite's size.
vtkSmartPointer<vtkSphereSource> ProxySphere(double radius)
{
  auto sphere = vtkSmartPointer<vtkSphereSource>::New();
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(8);
  return sphere;
}

// Spheres glyphed at `points` in `colouring`'s colours (its lookup table, scalar mode and
// range, array selection): of `radius`, or of radius times the point array `scales` names.
vtkSmartPointer<vtkMapper> GlyphedSpheres(
  vtkMapper* colouring, vtkPolyData* points, double radius, const char* scales)
{
  auto glyphs = vtkSmartPointer<vtkGlyph3DMapper>::New();
  glyphs->vtkMapper::ShallowCopy(colouring);
  glyphs->SetInputData(points);
  glyphs->SetSourceConnection(ProxySphere(radius)->GetOutputPort());
  glyphs->SetScaling(scales != nullptr);
  if (scales)
  {
    glyphs->SetScaleArray(scales);
    glyphs->SetScaleModeToScaleByMagnitude();
  }
  glyphs->OrientOff();
  return glyphs;
}
}

vtkSmartPointer<vtkMapper> ImposterProxies::SphereShapes(vtkActor* actor, double radius)
{
  return GlyphedSpheres(actor->GetMapper(), Input(actor), radius, nullptr);
}

namespace
{
// The points a splat mapper draws: its polydata, or its composite input's leaves' points
// and point data gathered into one (the arrays every leaf has).
vtkSmartPointer<vtkPolyData> SplatPoints(vtkMapper* mapper)
{
  vtkDataObject* input = mapper->GetInputDataObject(0, 0);
  auto* composite = vtkCompositeDataSet::SafeDownCast(input);
  if (!composite)
  {
    return vtkPolyData::SafeDownCast(input);
  }
  vtkNew<vtkAppendPolyData> append;
  vtkSmartPointer<vtkCompositeDataIterator> leaves;
  leaves.TakeReference(composite->NewIterator());
  for (leaves->InitTraversal(); !leaves->IsDoneWithTraversal(); leaves->GoToNextItem())
  {
    auto* leaf = vtkPointSet::SafeDownCast(leaves->GetCurrentDataObject());
    if (leaf && leaf->GetNumberOfPoints() > 0)
    {
      vtkNew<vtkPolyData> points;
      points->SetPoints(leaf->GetPoints());
      points->GetPointData()->ShallowCopy(leaf->GetPointData());
      append->AddInputData(points);
    }
  }
  if (append->GetNumberOfInputConnections(0) == 0)
  {
    return vtkSmartPointer<vtkPolyData>::New();
  }
  append->Update();
  return append->GetOutput();
}
}

vtkSmartPointer<vtkMapper> ImposterProxies::SplatShapes(vtkActor* actor)
{
  auto* mapper = vtkPointGaussianMapper::SafeDownCast(actor->GetMapper());
  vtkSmartPointer<vtkPolyData> input = SplatPoints(mapper);
  // Each splat's radius as VTK's splat mapper sizes it: the scale factor, times the scale
  // array's component when one is named, through the scale function when one is set.
  vtkDataArray* scales =
    mapper->GetScaleArray() ? input->GetPointData()->GetArray(mapper->GetScaleArray()) : nullptr;
  const int component = scales
    ? std::min(std::max(mapper->GetScaleArrayComponent(), 0), scales->GetNumberOfComponents() - 1)
    : 0;
  vtkNew<vtkFloatArray> radii;
  radii->SetName("voxelgi splat radius");
  radii->SetNumberOfTuples(input->GetNumberOfPoints());
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double r = mapper->GetScaleFactor() * (scales ? scales->GetComponent(i, component) : 1.0);
    r = scales && mapper->GetScaleFunction() ? mapper->GetScaleFunction()->GetValue(r) : r;
    radii->SetValue(i, static_cast<float>(std::isfinite(r) ? std::abs(r) : 0.0));
  }
  auto points = vtkSmartPointer<vtkPolyData>::New();
  points->ShallowCopy(input);
  points->GetPointData()->AddArray(radii);
  return GlyphedSpheres(mapper, points, 1.0, radii->GetName());
}

namespace
{
// The colour the molecule mapper gives atoms of atomic number `z`: the periodic table's
// (DiscreteByAtom, its default lookup table indexed by atomic number) or its single colour.
void MoleculeColour(vtkLookupTable* table, bool byAtom, const unsigned char* single,
  unsigned short z, unsigned char rgb[3])
{
  double rgba[4];
  table->GetTableValue(std::min<vtkIdType>(z, table->GetNumberOfTableValues() - 1), rgba);
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = byAtom ? static_cast<unsigned char>(std::lround(255.0 * rgba[c])) : single[c];
  }
}

// The atoms of `mapper`'s molecule as spheres of its atomic radii, in its colours.
vtkSmartPointer<vtkPolyData> AtomSpheres(vtkMoleculeMapper* mapper, vtkLookupTable* table)
{
  vtkMolecule* molecule = mapper->GetInput();
  vtkPeriodicTable* elements = mapper->GetPeriodicTable();
  const int type = mapper->GetAtomicRadiusType();
  const double scale = mapper->GetAtomicRadiusScaleFactor();
  vtkDataArray* custom =
    type == vtkMoleculeMapper::CustomArrayRadius && mapper->GetAtomicRadiusArrayName()
    ? molecule->GetVertexData()->GetArray(mapper->GetAtomicRadiusArrayName())
    : nullptr;
  const bool byAtom = mapper->GetAtomColorMode() == vtkMoleculeMapper::DiscreteByAtom;
  const vtkIdType n = molecule->GetNumberOfAtoms();
  vtkNew<vtkFloatArray> radii;
  radii->SetNumberOfTuples(n);
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("voxelgi colour");
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const unsigned short z = molecule->GetAtomAtomicNumber(i);
    const double r = custom ? custom->GetComponent(i, 0)
      : type == vtkMoleculeMapper::CovalentRadius ? scale * elements->GetCovalentRadius(z)
      : type == vtkMoleculeMapper::UnitRadius     ? scale
                                                  : scale * elements->GetVDWRadius(z);
    radii->SetValue(i, static_cast<float>(std::isfinite(r) ? std::abs(r) : 0.0));
    unsigned char rgb[3];
    MoleculeColour(table, byAtom, mapper->GetAtomColor(), z, rgb);
    colours->SetTypedTuple(i, rgb);
  }
  vtkNew<vtkPolyData> centres;
  centres->SetPoints(molecule->GetAtomicPositionArray());
  centres->GetPointData()->SetScalars(radii); // the glyphs' scale
  centres->GetPointData()->AddArray(colours); // copied to every point of each sphere
  vtkNew<vtkGlyph3D> glyphs;
  glyphs->SetInputData(centres);
  glyphs->SetSourceConnection(ProxySphere(1.0)->GetOutputPort());
  glyphs->SetScaleModeToScaleByScalar();
  glyphs->OrientOff();
  glyphs->Update();
  return glyphs->GetOutput();
}

// The bonds as cylinders of the bond radius: each half in its atom's colour (DiscreteByAtom)
// or the whole in the bond colour.
vtkSmartPointer<vtkPolyData> BondCylinders(vtkMoleculeMapper* mapper, vtkLookupTable* table)
{
  vtkMolecule* molecule = mapper->GetInput();
  const bool byAtom = mapper->GetBondColorMode() == vtkMoleculeMapper::DiscreteByAtom;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("voxelgi colour");
  colours->SetNumberOfComponents(3);
  auto add = [&](const double p[3], vtkIdType atom) {
    unsigned char rgb[3];
    MoleculeColour(
      table, byAtom, mapper->GetBondColor(), molecule->GetAtomAtomicNumber(atom), rgb);
    colours->InsertNextTypedTuple(rgb);
    return points->InsertNextPoint(p);
  };
  for (vtkIdType b = 0; b < molecule->GetNumberOfBonds(); ++b)
  {
    const vtkIdType ends[2] = { molecule->GetBond(b).GetBeginAtomId(),
      molecule->GetBond(b).GetEndAtomId() };
    double p[2][3], mid[3];
    molecule->GetAtomPosition(ends[0], p[0]);
    molecule->GetAtomPosition(ends[1], p[1]);
    for (int c = 0; c < 3; ++c)
    {
      mid[c] = 0.5 * (p[0][c] + p[1][c]);
    }
    for (int half = 0; half < (byAtom ? 2 : 1); ++half)
    {
      const vtkIdType segment[2] = { add(p[half], ends[half]),
        byAtom ? add(mid, ends[half]) : add(p[1], ends[1]) };
      lines->InsertNextCell(2, segment);
    }
  }
  vtkNew<vtkPolyData> axes;
  axes->SetPoints(points);
  axes->SetLines(lines);
  axes->GetPointData()->AddArray(colours);
  vtkNew<vtkTubeFilter> tubes;
  tubes->SetInputData(axes);
  tubes->SetRadius(mapper->GetBondRadius());
  tubes->SetNumberOfSides(8);
  tubes->CappingOn();
  tubes->Update();
  return tubes->GetOutput();
}
}

vtkSmartPointer<vtkMapper> ImposterProxies::MoleculeShapes(vtkActor* actor)
{
  auto* mapper = vtkMoleculeMapper::SafeDownCast(actor->GetMapper());
  vtkNew<vtkLookupTable> table;
  mapper->GetPeriodicTable()->GetDefaultLUT(table);
  vtkNew<vtkAppendPolyData> shapes;
  shapes->AddInputData(vtkSmartPointer<vtkPolyData>::New()); // nothing drawn: no triangles
  if (mapper->GetRenderAtoms())
  {
    shapes->AddInputData(AtomSpheres(mapper, table));
  }
  if (mapper->GetRenderBonds())
  {
    shapes->AddInputData(BondCylinders(mapper, table));
  }
  auto polygons = vtkSmartPointer<vtkPolyDataMapper>::New();
  polygons->SetInputConnection(shapes->GetOutputPort());
  polygons->SetScalarModeToUsePointFieldData();
  polygons->SelectColorArray("voxelgi colour");
  polygons->SetColorModeToDirectScalars();
  return polygons;
}

void ImposterProxies::Retain(const std::set<vtkProp*>& kept)
{
  for (auto it = this->Proxies.begin(); it != this->Proxies.end();)
  {
    it = kept.count(it->first) ? std::next(it) : this->Proxies.erase(it);
  }
}

}
