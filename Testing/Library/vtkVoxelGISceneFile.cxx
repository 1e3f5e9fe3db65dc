#include "vtkVoxelGISceneFile.h"

#include "vtkVoxelGIPass.h"

#include "vtkActor.h"
#include "vtkActor2D.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkFloatArray.h"
#include "vtkGeometryFilter.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_jsoncpp.h"

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
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

Vec3 FromJson(const Json::Value& v)
{
  return { v[0].asDouble(), v[1].asDouble(), v[2].asDouble() };
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
  return world->GetOutput();
}

// Why VTK's material of `actor` has no counterpart in Cycles, or empty.
std::string MaterialProblem(vtkActor* actor, const double background[3], bool colored)
{
  vtkProperty* p = actor->GetProperty();
  if (p->GetOpacity() < 1.0)
  {
    return "translucent (opacity " + std::to_string(p->GetOpacity()) + ")";
  }
  if (actor->GetTexture() || p->GetNumberOfTextures() > 0)
  {
    return "textured";
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
  vtkInformation* keys = actor->GetPropertyKeys();
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
  m["normals"] = normals;
  Json::Value vtk;
  vtk["ambient"] = p->GetAmbient();
  vtk["ambient_color"] = ToJson(p->GetAmbientColor());
  vtk["diffuse"] = p->GetDiffuse();
  vtk["diffuse_color"] = ToJson(p->GetDiffuseColor());
  vtk["specular"] = p->GetSpecular();
  vtk["specular_color"] = ToJson(p->GetSpecularColor());
  vtk["specular_power"] = p->GetSpecularPower();
  m["vtk"] = vtk;
  return m;
}

// The light as a scene light for the current camera, or a problem.
Json::Value Light(vtkLight* light, vtkCamera* camera, std::string& problem, std::string& note)
{
  Json::Value l;
  Vec3 position, focal;
  light->GetPosition(position.data());
  light->GetFocalPoint(focal.data());
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
  else if (attenuation[0] != 1.0 || attenuation[1] != 0.0 || attenuation[2] != 0.0)
  {
    problem = "attenuated point light (only VTK's default attenuation 1, 0, 0 is described)";
  }
  else
  {
    l["type"] = "point";
    l["position"] = ToJson(position.data());
  }
  return l;
}

void WriteObj(const std::string& stem, const std::vector<Surface>& surfaces)
{
  bool anyColors = false;
  for (const Surface& s : surfaces)
  {
    anyColors = anyColors || s.Colors;
  }
  std::ofstream mtl(stem + ".mtl");
  std::ofstream obj(stem + ".obj");
  obj.precision(9);
  obj << "mtllib " << BaseName(stem) << ".mtl\n";
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
  if (!this->FileName || !renderer)
  {
    vtkErrorMacro("Write needs a file name and a renderer");
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
  std::vector<Surface> surfaces;
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
    if (!actor)
    {
      problem(what, "not an actor (volumes, image slices and assemblies are not described)");
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

  const std::string stem = Stem(this->FileName);
  WriteObj(stem, surfaces);
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
  for (const Surface& s : surfaces)
  {
    scene["materials"][s.Name] = s.Material;
  }
  Json::StreamWriterBuilder builder;
  builder["indentation"] = "  ";
  builder["precision"] = 9;
  std::ofstream(this->FileName) << Json::writeString(builder, scene) << "\n";
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkVoxelGISceneFile::Read(vtkRenderer* renderer)
{
  Json::Value scene;
  {
    std::ifstream in(this->FileName ? this->FileName : "");
    Json::CharReaderBuilder builder;
    std::string errors;
    if (!renderer || !in || !Json::parseFromStream(builder, in, &scene, &errors))
    {
      vtkErrorMacro("cannot read the scene description " << (this->FileName ? this->FileName : "")
                                                         << " " << errors);
      return false;
    }
  }
  const std::string name = this->FileName;
  const size_t slash = name.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string() : name.substr(0, slash + 1);
  std::ifstream obj(dir + scene["obj"].asString());
  if (!obj)
  {
    vtkErrorMacro("cannot read " << dir + scene["obj"].asString());
    return false;
  }

  // The OBJ as written above: global points (with colours), normals, and per material its
  // faces; each material becomes one actor with the points its faces use.
  std::vector<Vec3> points, colors, normals;
  // per material its faces: corner point and normal indices (-1: none)
  std::map<std::string, std::vector<std::vector<std::pair<long, long>>>> faces;
  std::vector<std::string> order;
  std::string line, current;
  while (std::getline(obj, line))
  {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v" || tag == "vn")
    {
      Vec3 p{}, c{ 1.0, 1.0, 1.0 };
      s >> p[0] >> p[1] >> p[2];
      if (tag == "v" && (s >> c[0] >> c[1] >> c[2]))
      {
        colors.push_back(c);
      }
      (tag == "v" ? points : normals).push_back(p);
    }
    else if (tag == "usemtl")
    {
      s >> current;
      order.push_back(current);
    }
    else if (tag == "f")
    {
      std::vector<std::pair<long, long>> face;
      std::string corner;
      while (s >> corner)
      {
        const size_t slashes = corner.find("//");
        face.emplace_back(std::stol(corner) - 1,
          slashes == std::string::npos ? -1 : std::stol(corner.substr(slashes + 2)) - 1);
      }
      faces[current].push_back(face);
    }
  }

  for (const std::string& material : order)
  {
    const Json::Value& m = scene["materials"][material];
    const std::string normalMode = m["normals"].asString();
    const bool colored = m.get("vertex_colors", false).asBool();
    vtkNew<vtkPolyData> pd;
    vtkNew<vtkPoints> pts;
    vtkNew<vtkCellArray> polys;
    vtkNew<vtkFloatArray> n;
    n->SetNumberOfComponents(3);
    vtkNew<vtkUnsignedCharArray> rgb;
    rgb->SetNumberOfComponents(3);
    std::map<long, vtkIdType> local;
    for (const auto& face : faces[material])
    {
      polys->InsertNextCell(static_cast<int>(face.size()));
      for (const auto& corner : face)
      {
        auto found = local.find(corner.first);
        if (found == local.end())
        {
          found =
            local.emplace(corner.first, pts->InsertNextPoint(points[corner.first].data())).first;
          if (normalMode == "point")
          {
            n->InsertNextTuple(normals[corner.second].data());
          }
          for (int c = 0; colored && c < 3; ++c)
          {
            rgb->InsertNextValue(static_cast<unsigned char>(
              std::lround(255.0 * SrgbDecode(colors[corner.first][c]))));
          }
        }
        polys->InsertCellPoint(found->second);
      }
      if (normalMode == "cell")
      {
        n->InsertNextTuple(normals[face[0].second].data());
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
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    const Json::Value& vtk = m["vtk"];
    vtkProperty* p = actor->GetProperty();
    p->SetAmbient(vtk["ambient"].asDouble());
    p->SetAmbientColor(FromJson(vtk["ambient_color"]).data());
    p->SetDiffuse(vtk["diffuse"].asDouble());
    p->SetDiffuseColor(FromJson(vtk["diffuse_color"]).data());
    p->SetSpecular(vtk["specular"].asDouble());
    p->SetSpecularColor(FromJson(vtk["specular_color"]).data());
    p->SetSpecularPower(vtk["specular_power"].asDouble());
    if (m.isMember("emission"))
    {
      const Vec3 e = FromJson(m["emission"]);
      vtkVoxelGIPass::SetPropEmission(actor, e[0], e[1], e[2]);
    }
    renderer->AddActor(actor);
  }

  renderer->AutomaticLightCreationOff();
  for (const Json::Value& l : scene["lights"])
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetColor(FromJson(l["color"]).data());
    light->SetIntensity(l["intensity"].asDouble());
    if (l["type"].asString() == "directional")
    {
      const Vec3 d = FromJson(l["direction"]);
      light->SetPositional(false);
      light->SetPosition(-d[0], -d[1], -d[2]);
      light->SetFocalPoint(0.0, 0.0, 0.0);
    }
    else
    {
      light->SetPositional(true);
      light->SetConeAngle(90.0);
      light->SetPosition(FromJson(l["position"]).data());
    }
    if (l["headlight"].asBool())
    {
      light->SetLightTypeToHeadlight();
    }
    else if (l.isMember("camera_light"))
    {
      light->SetLightTypeToCameraLight();
      light->SetPosition(FromJson(l["camera_light"]["position"]).data());
      light->SetFocalPoint(FromJson(l["camera_light"]["focal_point"]).data());
    }
    renderer->AddLight(light);
  }
  const Json::Value& cam = scene["camera"];
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(FromJson(cam["position"]).data());
  camera->SetFocalPoint(FromJson(cam["focal_point"]).data());
  camera->SetViewUp(FromJson(cam["view_up"]).data());
  camera->SetViewAngle(cam["view_angle"].asDouble());
  renderer->SetBackground(FromJson(scene["background"]).data());
  renderer->ResetCameraClippingRange();
  this->Size[0] = scene["size"][0].asInt();
  this->Size[1] = scene["size"][1].asInt();
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
