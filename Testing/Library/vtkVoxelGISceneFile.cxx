#include "vtkVoxelGISceneFile.h"

#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkActor.h"
#include "vtkActor2D.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkGeometryFilter.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"
#include "vtk_jsoncpp.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

vtkStandardNewMacro(vtkVoxelGISceneFile);

namespace
{
using Vec3 = std::array<double, 3>;

Json::Value ToJson(const double* v, int n = 3)
{
  Json::Value array(Json::arrayValue);
  for (int i = 0; i < n; ++i)
  {
    array.append(v[i]);
  }
  return array;
}

Vec3 Scaled(double k, const double* c)
{
  return { k * c[0], k * c[1], k * c[2] };
}

// Blender's OBJ importer reads vertex colours as sRGB; VTK's are linear.
double SrgbEncode(double c)
{
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

double SrgbDecode(double c)
{
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

std::string Stem(const std::string& fileName)
{
  const std::string json = ".json";
  return fileName.size() > json.size() &&
      fileName.compare(fileName.size() - json.size(), json.size(), json) == 0
    ? fileName.substr(0, fileName.size() - json.size())
    : fileName;
}

std::string BaseName(const std::string& path)
{
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

bool Finite(const double* v, int n = 3)
{
  return std::all_of(v, v + n, [](double x) { return std::isfinite(x); });
}

// Why `pd` cannot be written as numbers that read back (NaN and infinity do not), or empty.
std::string NonFinite(vtkPolyData* pd)
{
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    if (!Finite(pd->GetPoint(i)))
    {
      return "non-finite point coordinates (point " + std::to_string(i) + ")";
    }
  }
  for (vtkDataArray* n : { pd->GetPointData()->GetNormals(), pd->GetCellData()->GetNormals() })
  {
    for (vtkIdType i = 0; n && i < n->GetNumberOfTuples(); ++i)
    {
      if (!Finite(n->GetTuple3(i)))
      {
        return "non-finite normals (tuple " + std::to_string(i) + ")";
      }
    }
  }
  return std::string();
}

// One actor as the description holds it: world-space polygons and VTK's material.
struct Surface
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Polygons;
  vtkSmartPointer<vtkUnsignedCharArray> Colors; // mapped point scalars, or null
  Json::Value Material;
};

const char* const ColorsName = "vtkVoxelGISceneFile colors";

// The actor's world-space polygons with its mapped point colours, or null with `problem` set.
vtkSmartPointer<vtkPolyData> Polygons(vtkActor* actor, std::string& problem)
{
  vtkMapper* mapper = actor->GetMapper();
  if (!vtkPolyDataMapper::SafeDownCast(mapper) && !mapper->IsA("vtkDataSetMapper"))
  {
    problem = std::string("mapper ") + mapper->GetClassName() +
      " (only polygonal and dataset mappers are described; vtkGlyph3D makes glyph surfaces)";
    return nullptr;
  }
  mapper->Update(); // the scene as the next render would draw it
  vtkDataObject* input = mapper->GetInputDataObject(0, 0);
  if (vtkCompositeDataSet::SafeDownCast(input) || !vtkDataSet::SafeDownCast(input))
  {
    problem = "composite or non-dataset input (merge the blocks, e.g. vtkAppendPolyData)";
    return nullptr;
  }
  vtkSmartPointer<vtkDataSet> data;
  data.TakeReference(vtkDataSet::SafeDownCast(input)->NewInstance());
  data->ShallowCopy(input);
  if (mapper->GetScalarVisibility())
  {
    int cellFlag = 0;
    vtkUnsignedCharArray* colors = mapper->MapScalars(data, 1.0, cellFlag);
    if (colors && cellFlag != 0)
    {
      problem = "cell or field scalar colours (only point scalars are described)";
      return nullptr;
    }
    if (colors)
    {
      vtkNew<vtkUnsignedCharArray> copy;
      copy->DeepCopy(colors);
      copy->SetName(ColorsName);
      data->GetPointData()->AddArray(copy);
    }
  }
  vtkSmartPointer<vtkPolyData> surface = vtkPolyData::SafeDownCast(data);
  if (!surface)
  {
    vtkNew<vtkGeometryFilter> geometry;
    geometry->SetInputData(data);
    geometry->Update();
    surface = geometry->GetOutput();
  }
  if (surface->GetNumberOfLines() > 0 || surface->GetNumberOfVerts() > 0)
  {
    problem = "lines or vertices, which VTK draws without area (vtkTubeFilter gives surfaces)";
    return nullptr;
  }
  if (surface->GetNumberOfPolys() + surface->GetNumberOfStrips() == 0)
  {
    return nullptr; // nothing to draw: left out, with no problem
  }
  // Polygons stay as they are (VTK and Cycles split them alike); strips become triangles.
  vtkNew<vtkTriangleFilter> strips;
  strips->SetInputData(surface);
  vtkNew<vtkTransform> transform;
  transform->SetMatrix(actor->GetMatrix());
  vtkNew<vtkTransformPolyDataFilter> world;
  if (surface->GetNumberOfStrips() > 0)
  {
    world->SetInputConnection(strips->GetOutputPort());
  }
  else
  {
    world->SetInputData(surface);
  }
  world->SetTransform(transform);
  world->Update();
  problem = NonFinite(world->GetOutput());
  return problem.empty() ? world->GetOutput() : nullptr;
}

// Why VTK's material of `actor` has no counterpart in Cycles, or empty.
std::string MaterialProblem(vtkActor* actor, const double background[3], bool colored)
{
  vtkProperty* p = actor->GetProperty();
  const double terms[] = { p->GetAmbient(), p->GetDiffuse(), p->GetSpecular(),
    p->GetSpecularPower() };
  vtkInformation* keys = actor->GetPropertyKeys();
  if (!Finite(terms, 4) || !Finite(p->GetAmbientColor()) || !Finite(p->GetDiffuseColor()) ||
    !Finite(p->GetSpecularColor()) ||
    (keys && keys->Has(vtkVoxelGIPass::EMISSION()) && !Finite(keys->Get(vtkVoxelGIPass::EMISSION()))))
  {
    return "non-finite material values";
  }
  if (actor->GetTexture() || p->GetNumberOfTextures() > 0)
  {
    return "textured";
  }
  // A translucent surface is written as Cycles' transparent BSDF over its own (Material).
  if (p->GetOpacity() < 1.0 &&
    (colored || (keys && keys->Has(vtkVoxelGIPass::EMISSION())) || p->GetSpecular() > 0.0))
  {
    return "translucent (opacity " + std::to_string(p->GetOpacity()) +
      ") with scalar colours, emission or a specular term";
  }
  if (p->GetOpacity() >= 1.0 && !actor->HasOpaqueGeometry())
  {
    return "translucent through its scalar colours' alpha";
  }
  if (p->GetInterpolation() == VTK_PBR)
  {
    return "PBR material";
  }
  if (!p->GetLighting())
  {
    return "unlit (lighting off)";
  }
  if (p->GetRepresentation() != VTK_SURFACE)
  {
    return "wireframe or points representation";
  }
  if (keys && keys->Has(vtkVoxelGIPass::EMISSION()))
  {
    return std::string();
  }
  // VTK's ambient term only has a physical counterpart as the background's sky light reflected
  // by the diffuse colour: Ka Ca = background x Kd Cd.
  const Vec3 ambient = Scaled(p->GetAmbient(), p->GetAmbientColor());
  const Vec3 diffuse = Scaled(p->GetDiffuse(), p->GetDiffuseColor());
  for (int c = 0; c < 3; ++c)
  {
    const double sky = colored ? 0.0 : background[c] * diffuse[c];
    if (std::abs(ambient[c] - sky) > 1e-6)
    {
      return colored ? std::string("ambient term with scalar colours")
                     : std::string("ambient term that is not the background's sky light");
    }
  }
  return std::string();
}

Json::Value Material(vtkActor* actor, bool colored, const std::string& normals)
{
  vtkProperty* p = actor->GetProperty();
  Json::Value m;
  const Vec3 diffuse = colored ? Vec3{ p->GetDiffuse(), p->GetDiffuse(), p->GetDiffuse() }
                               : Scaled(p->GetDiffuse(), p->GetDiffuseColor());
  m["diffuse"] = ToJson(diffuse.data());
  m["specular"] = ToJson(Scaled(p->GetSpecular(), p->GetSpecularColor()).data());
  m["specular_power"] = p->GetSpecularPower();
  vtkInformation* keys = actor->GetPropertyKeys();
  if (keys && keys->Has(vtkVoxelGIPass::EMISSION()))
  {
    m["emission"] = ToJson(keys->Get(vtkVoxelGIPass::EMISSION()));
  }
  if (colored)
  {
    m["vertex_colors"] = true;
  }
  if (p->GetOpacity() < 1.0)
  {
    // Of the light that reaches it, (1 - opacity) passes, tinted by its colour as much as it
    // is opaque (as the pass's shadows let it through); the camera sees through it untinted,
    // as VTK blends it.
    const double a = p->GetOpacity();
    const double* c = p->GetDiffuseColor();
    const double tint[3] = { 1.0 - a + a * c[0], 1.0 - a + a * c[1], 1.0 - a + a * c[2] };
    m["opacity"] = a;
    m["transmit"] = ToJson(tint);
  }
  m["normals"] = normals;
  Json::Value vtk;
  vtk["ambient"] = p->GetAmbient();
  vtk["ambient_color"] = ToJson(p->GetAmbientColor());
  vtk["diffuse"] = p->GetDiffuse();
  vtk["diffuse_color"] = ToJson(p->GetDiffuseColor());
  vtk["specular"] = p->GetSpecular();
  vtk["specular_color"] = ToJson(p->GetSpecularColor());
  vtk["specular_power"] = p->GetSpecularPower();
  if (p->GetOpacity() < 1.0)
  {
    vtk["opacity"] = p->GetOpacity();
  }
  m["vtk"] = vtk;
  return m;
}

/// A homogeneous volume (constant opacity and colour over its scalars) as Cycles' extinction:
/// VTK's opacity alpha per unit distance u is the density -ln(1 - alpha) / u per world unit.
/// Empty with `problem` when the volume is anything else.
Json::Value HomogeneousVolume(vtkVolume* volume, std::string& problem)
{
  vtkAbstractVolumeMapper* mapper = volume->GetMapper();
  auto* image = mapper ? vtkImageData::SafeDownCast(mapper->GetDataSetInput()) : nullptr;
  int cellFlag = 0;
  vtkDataArray* scalars = image ? vtkAbstractMapper::GetScalars(image, mapper->GetScalarMode(),
                                    mapper->GetArrayAccessMode(), mapper->GetArrayId(),
                                    mapper->GetArrayName(), cellFlag)
                                : nullptr;
  auto* rayCast = vtkVolumeMapper::SafeDownCast(mapper);
  vtkVolumeProperty* property = volume->GetProperty();
  if (!scalars || cellFlag || scalars->GetNumberOfComponents() != 1 ||
    !image->GetDirectionMatrix()->IsIdentity())
  {
    problem = "a volume other than axis-aligned image data with one point scalar";
  }
  else if ((rayCast && rayCast->GetBlendMode() != vtkVolumeMapper::COMPOSITE_BLEND) ||
    property->GetShade() || property->GetColorChannels() != 3)
  {
    problem = "a shaded, grey or non-composite volume (VTK's own volume lighting)";
  }
  if (!problem.empty())
  {
    return Json::Value();
  }
  double range[2];
  scalars->GetRange(range);
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity();
  vtkColorTransferFunction* color = property->GetRGBTransferFunction();
  const double alpha = opacity->GetValue(range[0]);
  double rgb[3];
  color->GetColor(range[0], rgb);
  for (int i = 0; i <= 16; ++i)
  {
    const double s = range[0] + (range[1] - range[0]) * i / 16.0;
    double c[3];
    color->GetColor(s, c);
    if (std::abs(opacity->GetValue(s) - alpha) > 1e-9 || std::abs(c[0] - rgb[0]) > 1e-9 ||
      std::abs(c[1] - rgb[1]) > 1e-9 || std::abs(c[2] - rgb[2]) > 1e-9)
    {
      problem = "transfer functions that vary over the data (only homogeneous volumes)";
      return Json::Value();
    }
  }
  const double unit = property->GetScalarOpacityUnitDistance();
  if (!(alpha > 0.0 && alpha < 1.0 && unit > 0.0))
  {
    problem = "opacity 0 or 1 per unit distance (no finite density)";
    return Json::Value();
  }
  Json::Value v;
  v["bounds"] = ToJson(image->GetBounds(), 6);
  Json::Value matrix(Json::arrayValue);
  for (int i = 0; i < 16; ++i)
  {
    matrix.append(volume->GetMatrix()->GetElement(i / 4, i % 4));
  }
  v["matrix"] = matrix;
  v["density"] = -std::log(1.0 - alpha) / unit;
  v["color"] = ToJson(rgb);
  return v;
}

// The light as a scene light for the current camera, or a problem.
Json::Value Light(vtkLight* light, vtkCamera* camera, std::string& problem, std::string& note)
{
  Json::Value l;
  Vec3 position, focal;
  light->GetPosition(position.data());
  light->GetFocalPoint(focal.data());
  const double intensity = light->GetIntensity();
  if (!Finite(position.data()) || !Finite(focal.data()) || !Finite(light->GetDiffuseColor()) ||
    !Finite(&intensity, 1))
  {
    problem = "non-finite position, focal point, colour or intensity";
    return l;
  }
  if (light->LightTypeIsHeadlight())
  {
    camera->GetPosition(position.data());
    camera->GetFocalPoint(focal.data());
    note = "the headlight is written as a scene light for the current camera";
  }
  else if (light->LightTypeIsCameraLight())
  {
    // Read() makes it a camera light again, placed as in the camera's frame.
    Json::Value follows;
    follows["position"] = ToJson(position.data());
    follows["focal_point"] = ToJson(focal.data());
    l["camera_light"] = follows;
    vtkMatrix4x4* m = camera->GetCameraLightTransformMatrix();
    for (Vec3* p : { &position, &focal })
    {
      double in[4] = { (*p)[0], (*p)[1], (*p)[2], 1.0 }, out[4];
      m->MultiplyPoint(in, out);
      *p = { out[0] / out[3], out[1] / out[3], out[2] / out[3] };
    }
    note = "camera lights are written as scene lights for the current camera";
  }
  // Whether it follows the camera (Cycles sees the light of the current camera alone; an
  // orbit in the error study moves it).
  l["headlight"] = light->LightTypeIsHeadlight() != 0;
  l["color"] = ToJson(light->GetDiffuseColor());
  l["intensity"] = light->GetIntensity();
  const double* attenuation = light->GetAttenuationValues();
  if (!light->GetPositional())
  {
    Vec3 d = { focal[0] - position[0], focal[1] - position[1], focal[2] - position[2] };
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(length > 0.0))
    {
      problem = "a directional light whose position and focal point coincide";
      return l;
    }
    l["type"] = "directional";
    l["direction"] = ToJson(Scaled(1.0 / length, d.data()).data());
  }
  else if (light->GetConeAngle() < 90.0)
  {
    problem = "spot light (cone angle " + std::to_string(light->GetConeAngle()) + ")";
  }
  else if (attenuation[0] == 0.0 && attenuation[1] == 0.0 && attenuation[2] > 0.0)
  {
    // Inverse-square falloff, physical: I / (c2 d^2) is a point light of intensity I / c2.
    l["type"] = "point";
    l["falloff"] = "inverse_square";
    l["intensity"] = intensity / attenuation[2];
    l["position"] = ToJson(position.data());
  }
  else if (attenuation[0] != 1.0 || attenuation[1] != 0.0 || attenuation[2] != 0.0)
  {
    problem = "attenuated point light (only VTK's default attenuation 1, 0, 0 and inverse "
              "square 0, 0, c are described)";
  }
  else
  {
    l["type"] = "point";
    l["position"] = ToJson(position.data());
  }
  return l;
}

void WriteObj(std::ostream& obj, std::ostream& mtl, const std::string& mtlName,
  const std::vector<Surface>& surfaces)
{
  bool anyColors = false;
  for (const Surface& s : surfaces)
  {
    anyColors = anyColors || s.Colors;
  }
  obj.precision(9);
  obj << "mtllib " << mtlName << "\n";
  vtkIdType pointBase = 1, normalBase = 1;
  for (const Surface& s : surfaces)
  {
    mtl << "newmtl " << s.Name << "\nKd 0.8 0.8 0.8\n";
    obj << "g " << s.Name << "\nusemtl " << s.Name << "\n";
    vtkPolyData* pd = s.Polygons;
    for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
    {
      double x[3];
      pd->GetPoint(i, x);
      obj << "v " << x[0] << " " << x[1] << " " << x[2];
      // The importer keeps vertex colours only if every vertex has one: others get white,
      // which their materials do not read.
      for (int c = 0; anyColors && c < 3; ++c)
      {
        obj << " " << (s.Colors ? SrgbEncode(s.Colors->GetComponent(i, c) / 255.0) : 1.0);
      }
      obj << "\n";
    }
    const std::string normals = s.Material["normals"].asString();
    vtkDataArray* n = normals == "point" ? pd->GetPointData()->GetNormals()
                                         : pd->GetCellData()->GetNormals();
    const vtkIdType normalCount = normals == "none" ? 0 : n->GetNumberOfTuples();
    for (vtkIdType i = 0; i < normalCount; ++i)
    {
      const double* v = n->GetTuple3(i);
      obj << "vn " << v[0] << " " << v[1] << " " << v[2] << "\n";
    }
    vtkIdType cell = 0;
    const vtkIdType* ids = nullptr;
    vtkIdType count = 0;
    vtkCellArray* polys = pd->GetPolys();
    for (polys->InitTraversal(); polys->GetNextCell(count, ids); ++cell)
    {
      obj << "f";
      for (vtkIdType k = 0; k < count; ++k)
      {
        obj << " " << pointBase + ids[k];
        if (normals != "none")
        {
          obj << "//" << normalBase + (normals == "point" ? ids[k] : cell);
        }
      }
      obj << "\n";
    }
    pointBase += pd->GetNumberOfPoints();
    normalBase += normalCount;
  }
}
}

//------------------------------------------------------------------------------
vtkVoxelGISceneFile::~vtkVoxelGISceneFile()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
bool vtkVoxelGISceneFile::Write(vtkRenderer* renderer)
{
  this->Problems.clear();
  this->Notes.clear();
  const std::string fileName = this->FileName ? this->FileName : "";
  const std::string stem = Stem(fileName);
  auto endsWith = [&fileName](const std::string& end) {
    return fileName.size() >= end.size() &&
      fileName.compare(fileName.size() - end.size(), end.size(), end) == 0;
  };
  if (!renderer || stem.empty() || endsWith(".obj") || endsWith(".mtl"))
  {
    vtkErrorMacro("Write needs a renderer and a file name (not ending in .obj or .mtl, which "
                  "the description writes beside it)");
    return false;
  }
  auto problem = [this](const std::string& what, const std::string& why) {
    this->Problems += what + ": " + why + "\n";
  };
  auto note = [this](const std::string& text) {
    if (this->Notes.find(text + "\n") == std::string::npos)
    {
      this->Notes += text + "\n";
    }
  };
  vtkCamera* camera = renderer->GetActiveCamera();
  const double viewAngle = camera->GetViewAngle();
  if (!Finite(camera->GetPosition()) || !Finite(camera->GetFocalPoint()) ||
    !Finite(camera->GetViewUp()) || !Finite(&viewAngle, 1))
  {
    problem("camera", "non-finite position, focal point, view up or view angle");
  }
  if (camera->GetParallelProjection())
  {
    problem("camera", "parallel projection");
  }
  if (camera->GetUseHorizontalViewAngle())
  {
    problem("camera", "horizontal view angle");
  }
  if (renderer->GetGradientBackground() || renderer->GetTexturedBackground())
  {
    problem("background", "gradient or textured (only a uniform colour is a sky)");
  }
  if (renderer->GetUseImageBasedLighting())
  {
    problem("renderer", "image-based lighting");
  }

  double background[3];
  renderer->GetBackground(background);
  if (!Finite(background))
  {
    problem("background", "non-finite colour");
  }
  std::vector<Surface> surfaces;
  Json::Value volumes(Json::arrayValue);
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  int index = 0;
  while (vtkProp* prop = props->GetNextProp(it))
  {
    const std::string what = std::string("prop ") + std::to_string(index++) + " (" +
      prop->GetClassName() + ")";
    vtkActor* actor = vtkActor::SafeDownCast(prop);
    if (!prop->GetVisibility() || (actor && !actor->GetMapper()))
    {
      continue;
    }
    if (vtkActor2D::SafeDownCast(prop))
    {
      note("overlays (2D actors) are left out: Cycles renders the 3D scene only");
      continue;
    }
    if (auto* volume = vtkVolume::SafeDownCast(prop))
    {
      std::string why;
      Json::Value v = HomogeneousVolume(volume, why);
      if (!why.empty())
      {
        problem(what, why);
      }
      else
      {
        volumes.append(v);
      }
      continue;
    }
    if (!actor)
    {
      problem(what, "not an actor (image slices and assemblies are not described)");
      continue;
    }
    std::string why;
    vtkSmartPointer<vtkPolyData> polygons = Polygons(actor, why);
    if (polygons)
    {
      auto* colors = vtkUnsignedCharArray::SafeDownCast(
        polygons->GetPointData()->GetArray(ColorsName));
      why = MaterialProblem(actor, background, colors != nullptr);
      const std::string normals = polygons->GetPointData()->GetNormals() ? "point"
        : polygons->GetCellData()->GetNormals()                          ? "cell"
                                                                          : "none";
      surfaces.push_back({ "actor" + std::to_string(surfaces.size()), polygons, colors,
        Material(actor, colors != nullptr, normals) });
    }
    else if (why.empty())
    {
      note("actors without polygons are left out");
    }
    if (!why.empty())
    {
      problem(what, why);
    }
  }

  Json::Value lights(Json::arrayValue);
  vtkLightCollection* lightCollection = renderer->GetLights();
  if (lightCollection->GetNumberOfItems() == 0 && renderer->GetAutomaticLightCreation())
  {
    // what the renderer creates on its first render
    renderer->CreateLight();
  }
  lightCollection->InitTraversal(it);
  index = 0;
  while (vtkLight* light = lightCollection->GetNextLight(it))
  {
    const std::string what = "light " + std::to_string(index++);
    if (!light->GetSwitch() || light->GetIntensity() == 0.0)
    {
      continue;
    }
    std::string why, lightNote;
    Json::Value l = Light(light, camera, why, lightNote);
    if (!why.empty())
    {
      problem(what, why);
      continue;
    }
    if (!lightNote.empty())
    {
      note(lightNote);
    }
    lights.append(l);
  }

  if (!this->Problems.empty())
  {
    vtkErrorMacro("The scene cannot be described for the path tracer:\n" << this->Problems);
    return false;
  }
  if (this->Size[0] <= 0 || this->Size[1] <= 0)
  {
    const int* size = renderer->GetRenderWindow() ? renderer->GetSize() : nullptr;
    const bool known = size && size[0] > 0 && size[1] > 0;
    this->Size[0] = known ? size[0] : 200;
    this->Size[1] = known ? size[1] : 200;
  }

  Json::Value scene;
  scene["obj"] = BaseName(stem) + ".obj";
  scene["size"] = Json::Value(Json::arrayValue);
  scene["size"].append(this->Size[0]);
  scene["size"].append(this->Size[1]);
  Json::Value& cam = scene["camera"];
  cam["position"] = ToJson(camera->GetPosition());
  cam["focal_point"] = ToJson(camera->GetFocalPoint());
  cam["view_up"] = ToJson(camera->GetViewUp());
  cam["view_angle"] = camera->GetViewAngle();
  scene["background"] = ToJson(background);
  scene["lights"] = lights;
  if (!volumes.empty())
  {
    scene["volumes"] = volumes;
  }
  for (const Surface& s : surfaces)
  {
    scene["materials"][s.Name] = s.Material;
  }
  Json::StreamWriterBuilder builder;
  builder["indentation"] = "  ";
  builder["precision"] = 9;
  // The description first: a name that cannot be written stops Write() before it makes
  // the OBJ and MTL files beside it.
  const std::string paths[] = { fileName, stem + ".obj", stem + ".mtl" };
  bool existed[3];
  for (int i = 0; i < 3; ++i)
  {
    existed[i] = std::filesystem::exists(paths[i]);
  }
  std::ofstream json(paths[0]);
  json << Json::writeString(builder, scene) << "\n";
  json.close();
  bool written = !json.fail();
  if (written)
  {
    std::ofstream obj(paths[1]), mtl(paths[2]);
    WriteObj(obj, mtl, BaseName(stem) + ".mtl", surfaces);
    obj.close();
    mtl.close();
    written = !obj.fail() && !mtl.fail();
  }
  if (!written)
  {
    std::error_code ignored;
    for (int i = 0; i < 3; ++i)
    {
      if (!existed[i])
      {
        std::filesystem::remove(paths[i], ignored); // no half-written description
      }
    }
    vtkErrorMacro("cannot write the scene description " << fileName << " and the OBJ and MTL "
                                                         "files beside it");
    return false;
  }
  this->Modified();
  return true;
}

namespace
{
// What a damaged description lacks, by field or line: Read() reports it and adds nothing.
struct Damaged : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

const Json::Value& Field(const Json::Value& object, const char* key, const std::string& where)
{
  if (!object.isObject() || !object.isMember(key))
  {
    throw Damaged(where + " has no \"" + key + "\"");
  }
  return object[key];
}

double Number(const Json::Value& v, const std::string& what)
{
  if (!v.isNumeric() || !std::isfinite(v.asDouble()))
  {
    throw Damaged(what + " is not a finite number");
  }
  return v.asDouble();
}

Vec3 Vector(const Json::Value& v, const std::string& what)
{
  if (!v.isArray() || v.size() != 3)
  {
    throw Damaged(what + " is not three numbers");
  }
  return { Number(v[0], what), Number(v[1], what), Number(v[2], what) };
}

std::string Text(const Json::Value& v, const std::string& what)
{
  if (!v.isString())
  {
    throw Damaged(what + " is not a string");
  }
  return v.asString();
}

// The OBJ as Write() makes it, and as other writers do (relative indices, v/t/n corners).
struct Obj
{
  struct Corner
  {
    size_t Point;
    long Normal; // -1: none
  };
  std::vector<Vec3> Points, Normals;
  std::vector<Vec3> Colors; // per point: the written colour, or -1 where the point has none
  std::map<std::string, std::vector<std::vector<Corner>>> Faces; // per material
  std::vector<std::string> Materials; // in the order of first use
};

// Whether all of `token` is one number of type T.
template <typename T>
bool WholeNumber(const std::string& token, T& value)
{
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
}

double ObjNumber(const std::string& token, const std::string& where)
{
  double x = 0.0;
  if (!WholeNumber(token, x) || !std::isfinite(x))
  {
    throw Damaged(where + ": \"" + token + "\" is not a finite number");
  }
  return x;
}

// A 1-based index, or a relative one (-1: the last defined), into `count` items.
long ObjIndex(const std::string& token, size_t count, const std::string& where)
{
  long k = 0;
  const bool number = WholeNumber(token, k);
  const long resolved = k > 0 ? k - 1 : static_cast<long>(count) + k;
  if (!number || k == 0 || resolved < 0 || resolved >= static_cast<long>(count))
  {
    throw Damaged(where + ": index \"" + token + "\" names none of the " +
      std::to_string(count) + " defined before it");
  }
  return resolved;
}

Obj ReadObj(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
  {
    throw Damaged("cannot open " + path);
  }
  Obj obj;
  std::string line, material;
  for (size_t number = 1; std::getline(in, line); ++number)
  {
    const std::string where = path + " line " + std::to_string(number);
    std::istringstream s(line);
    std::vector<std::string> tokens;
    for (std::string token; s >> token;)
    {
      tokens.push_back(token);
    }
    const std::string tag = tokens.empty() ? std::string() : tokens[0];
    if (tag == "v" || tag == "vn")
    {
      const size_t values = tokens.size() - 1;
      if (values != 3 && (tag == "vn" || values != 6))
      {
        throw Damaged(where + ": " + tag + " needs " + (tag == "v" ? "3 or 6" : "3") + " numbers");
      }
      Vec3 p, c{ -1.0, -1.0, -1.0 };
      for (int k = 0; k < 3; ++k)
      {
        p[k] = ObjNumber(tokens[1 + k], where);
        c[k] = values == 6 ? ObjNumber(tokens[4 + k], where) : c[k];
      }
      (tag == "v" ? obj.Points : obj.Normals).push_back(p);
      if (tag == "v")
      {
        obj.Colors.push_back(c);
      }
    }
    else if (tag == "usemtl")
    {
      material = tokens.size() > 1 ? tokens[1] : std::string();
      if (!obj.Faces.count(material))
      {
        obj.Materials.push_back(material);
        obj.Faces[material];
      }
    }
    else if (tag == "f")
    {
      if (tokens.size() < 4 || obj.Materials.empty())
      {
        throw Damaged(where + ": a face needs 3 corners and a material (usemtl) before it");
      }
      std::vector<Obj::Corner> face;
      for (size_t k = 1; k < tokens.size(); ++k)
      {
        // v, v/t, v//n or v/t/n: the texture coordinate is not read
        const std::string& corner = tokens[k];
        const size_t first = corner.find('/');
        const size_t second =
          first == std::string::npos ? std::string::npos : corner.find('/', first + 1);
        const size_t point = ObjIndex(corner.substr(0, first), obj.Points.size(), where);
        const long normal = second == std::string::npos
          ? -1
          : ObjIndex(corner.substr(second + 1), obj.Normals.size(), where);
        face.push_back({ point, normal });
      }
      obj.Faces[material].push_back(face);
    }
  }
  return obj;
}

// The actor of one material: the points its faces use, with their normals and colours.
vtkSmartPointer<vtkActor> MaterialActor(
  const Obj& obj, const std::string& material, const Json::Value& m, const std::string& where)
{
  const std::string normalMode = Text(Field(m, "normals", where), where + ".normals");
  if (normalMode != "point" && normalMode != "cell" && normalMode != "none")
  {
    throw Damaged(where + ".normals is not point, cell or none");
  }
  const Json::Value& colorFlag = m.get("vertex_colors", false);
  if (!colorFlag.isBool())
  {
    throw Damaged(where + ".vertex_colors is not true or false");
  }
  const bool colored = colorFlag.asBool();
  vtkNew<vtkPolyData> pd;
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkFloatArray> n;
  n->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetNumberOfComponents(3);
  std::map<size_t, vtkIdType> local;
  auto normal = [&](const Obj::Corner& corner) {
    if (corner.Normal < 0)
    {
      throw Damaged(where + ": a face corner without the normal its mode needs");
    }
    n->InsertNextTuple(obj.Normals[corner.Normal].data());
  };
  for (const auto& face : obj.Faces.at(material))
  {
    polys->InsertNextCell(static_cast<int>(face.size()));
    for (const auto& corner : face)
    {
      auto found = local.find(corner.Point);
      if (found == local.end())
      {
        found = local.emplace(corner.Point, pts->InsertNextPoint(obj.Points[corner.Point].data()))
                  .first;
        if (normalMode == "point")
        {
          normal(corner);
        }
        const Vec3& c = obj.Colors[corner.Point];
        for (int k = 0; colored && k < 3; ++k)
        {
          if (c[k] < 0.0 || c[k] > 1.0)
          {
            throw Damaged(where + ": a vertex without a colour in [0, 1]");
          }
          rgb->InsertNextValue(static_cast<unsigned char>(std::lround(255.0 * SrgbDecode(c[k]))));
        }
      }
      polys->InsertCellPoint(found->second);
    }
    if (normalMode == "cell")
    {
      normal(face[0]);
    }
  }
  pd->SetPoints(pts);
  pd->SetPolys(polys);
  if (normalMode == "point")
  {
    pd->GetPointData()->SetNormals(n);
  }
  else if (normalMode == "cell")
  {
    pd->GetCellData()->SetNormals(n);
  }
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(pd);
  mapper->SetScalarVisibility(colored);
  if (colored)
  {
    pd->GetPointData()->SetScalars(rgb);
    mapper->SetColorModeToDirectScalars();
  }
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  const Json::Value& vtk = Field(m, "vtk", where);
  const std::string v = where + ".vtk.";
  vtkProperty* p = actor->GetProperty();
  p->SetAmbient(Number(Field(vtk, "ambient", v), v + "ambient"));
  p->SetAmbientColor(Vector(Field(vtk, "ambient_color", v), v + "ambient_color").data());
  p->SetDiffuse(Number(Field(vtk, "diffuse", v), v + "diffuse"));
  p->SetDiffuseColor(Vector(Field(vtk, "diffuse_color", v), v + "diffuse_color").data());
  p->SetSpecular(Number(Field(vtk, "specular", v), v + "specular"));
  p->SetSpecularColor(Vector(Field(vtk, "specular_color", v), v + "specular_color").data());
  p->SetSpecularPower(Number(Field(vtk, "specular_power", v), v + "specular_power"));
  if (vtk.isMember("opacity"))
  {
    p->SetOpacity(Number(vtk["opacity"], v + "opacity"));
  }
  if (m.isMember("emission"))
  {
    const Vec3 e = Vector(m["emission"], where + ".emission");
    vtkVoxelGIPass::SetPropEmission(actor, e[0], e[1], e[2]);
  }
  return actor;
}

/// The volume a description's entry describes: constant scalars over its bounds through
/// constant transfer functions of opacity 1 - exp(-density) per unit distance.
vtkSmartPointer<vtkVolume> HomogeneousVolume(const Json::Value& v, const std::string& where)
{
  const Json::Value& bounds = Field(v, "bounds", where);
  const Json::Value& matrix = Field(v, "matrix", where);
  if (!bounds.isArray() || bounds.size() != 6 || !matrix.isArray() || matrix.size() != 16)
  {
    throw Damaged(where + ": bounds are not 6 numbers or the matrix not 16");
  }
  double b[6], m[16];
  for (Json::ArrayIndex i = 0; i < 6; ++i)
  {
    b[i] = Number(bounds[i], where + ".bounds");
  }
  for (Json::ArrayIndex i = 0; i < 16; ++i)
  {
    m[i] = Number(matrix[i], where + ".matrix");
  }
  const double density = Number(Field(v, "density", where), where + ".density");
  const Vec3 color = Vector(Field(v, "color", where), where + ".color");
  if (!(density > 0.0) || !(b[0] < b[1] && b[2] < b[3] && b[4] < b[5]))
  {
    throw Damaged(where + ": no positive density or empty bounds");
  }
  vtkSmartPointer<vtkVolume> volume =
    vtkVoxelGIScenes::MakeHomogeneousVolume(b, 1.0 - std::exp(-density), color.data());
  vtkNew<vtkMatrix4x4> user;
  user->DeepCopy(m);
  volume->SetUserMatrix(user);
  return volume;
}

vtkSmartPointer<vtkLight> SceneLight(const Json::Value& l, const std::string& where)
{
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  light->SetColor(Vector(Field(l, "color", where), where + ".color").data());
  light->SetIntensity(Number(Field(l, "intensity", where), where + ".intensity"));
  const std::string type = Text(Field(l, "type", where), where + ".type");
  if (type == "directional")
  {
    const Vec3 d = Vector(Field(l, "direction", where), where + ".direction");
    light->SetPositional(false);
    light->SetPosition(-d[0], -d[1], -d[2]);
    light->SetFocalPoint(0.0, 0.0, 0.0);
  }
  else if (type == "point")
  {
    light->SetPositional(true);
    light->SetConeAngle(90.0);
    light->SetPosition(Vector(Field(l, "position", where), where + ".position").data());
    const std::string falloff = l.get("falloff", "none").asString();
    if (falloff == "inverse_square")
    {
      light->SetAttenuationValues(0.0, 0.0, 1.0);
    }
    else if (falloff != "none")
    {
      throw Damaged(where + ".falloff is neither none nor inverse_square");
    }
  }
  else
  {
    throw Damaged(where + ".type is neither directional nor point");
  }
  if (l.get("headlight", false).asBool())
  {
    light->SetLightTypeToHeadlight();
  }
  else if (l.isMember("camera_light"))
  {
    const Json::Value& c = l["camera_light"];
    light->SetLightTypeToCameraLight();
    light->SetPosition(Vector(Field(c, "position", where), where + ".camera_light").data());
    light->SetFocalPoint(Vector(Field(c, "focal_point", where), where + ".camera_light").data());
  }
  return light;
}
}

//------------------------------------------------------------------------------
bool vtkVoxelGISceneFile::Read(vtkRenderer* renderer)
{
  const std::string name = this->FileName ? this->FileName : "";
  std::vector<vtkSmartPointer<vtkActor>> actors;
  std::vector<vtkSmartPointer<vtkLight>> lights;
  std::vector<vtkSmartPointer<vtkVolume>> volumes;
  Vec3 position, focal, up, background;
  double viewAngle = 0.0;
  int size[2];
  // Everything is read and checked before the renderer changes: a damaged file adds nothing.
  try
  {
    if (!renderer)
    {
      throw Damaged("no renderer to read into");
    }
    Json::Value scene;
    std::ifstream in(name);
    Json::CharReaderBuilder builder;
    std::string errors;
    if (!in || !Json::parseFromStream(builder, in, &scene, &errors))
    {
      throw Damaged("not a JSON file " + errors);
    }
    const size_t slash = name.find_last_of('/');
    const std::string dir = slash == std::string::npos ? std::string() : name.substr(0, slash + 1);
    const Obj obj = ReadObj(dir + Text(Field(scene, "obj", "the description"), "obj"));
    const Json::Value& materials = Field(scene, "materials", "the description");
    for (const std::string& material : obj.Materials)
    {
      actors.push_back(MaterialActor(obj, material,
        Field(materials, material.c_str(), "materials"), "materials." + material));
    }
    const Json::Value& lightList = Field(scene, "lights", "the description");
    if (!lightList.isArray())
    {
      throw Damaged("lights is not a list");
    }
    for (Json::ArrayIndex i = 0; i < lightList.size(); ++i)
    {
      lights.push_back(SceneLight(lightList[i], "lights[" + std::to_string(i) + "]"));
    }
    const Json::Value& volumeList = scene["volumes"]; // optional
    for (Json::ArrayIndex i = 0; volumeList.isArray() && i < volumeList.size(); ++i)
    {
      volumes.push_back(HomogeneousVolume(volumeList[i], "volumes[" + std::to_string(i) + "]"));
    }
    const Json::Value& cam = Field(scene, "camera", "the description");
    position = Vector(Field(cam, "position", "camera"), "camera.position");
    focal = Vector(Field(cam, "focal_point", "camera"), "camera.focal_point");
    up = Vector(Field(cam, "view_up", "camera"), "camera.view_up");
    viewAngle = Number(Field(cam, "view_angle", "camera"), "camera.view_angle");
    if (!(viewAngle > 0.0 && viewAngle < 180.0) || position == focal || up == Vec3{})
    {
      throw Damaged("the camera has no view (angle, focal point or view up)");
    }
    background = Vector(Field(scene, "background", "the description"), "background");
    const Json::Value& imageSize = Field(scene, "size", "the description");
    for (Json::ArrayIndex i = 0; i < 2; ++i)
    {
      if (!imageSize.isArray() || imageSize.size() != 2 || !imageSize[i].isInt() ||
        imageSize[i].asInt() < 1 || imageSize[i].asInt() > 16384)
      {
        throw Damaged("size is not two pixel counts in [1, 16384]");
      }
      size[i] = imageSize[i].asInt();
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("cannot read the scene description " << name << ": " << e.what());
    return false;
  }

  for (vtkActor* actor : actors)
  {
    renderer->AddActor(actor);
  }
  for (vtkVolume* volume : volumes)
  {
    renderer->AddVolume(volume);
  }
  renderer->AutomaticLightCreationOff();
  for (vtkLight* light : lights)
  {
    renderer->AddLight(light);
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(position.data());
  camera->SetFocalPoint(focal.data());
  camera->SetViewUp(up.data());
  camera->SetViewAngle(viewAngle);
  renderer->SetBackground(background.data());
  renderer->ResetCameraClippingRange();
  this->Size[0] = size[0];
  this->Size[1] = size[1];
  return true;
}

//------------------------------------------------------------------------------
void vtkVoxelGISceneFile::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Size: " << this->Size[0] << " " << this->Size[1] << "\n";
  os << indent << "Problems: " << this->Problems << "\n";
  os << indent << "Notes: " << this->Notes << "\n";
}
