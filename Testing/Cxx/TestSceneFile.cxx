// The scene description of the error study (vtkVoxelGISceneFile), one case per run:
//
//   TestSceneFile CASE     (CTest runs each as VoxelGI::SceneFile.CASE)
//
// SCENE (a name vtkVoxelGIScenes::AddScene knows): the built-in
// scene, written and read back into a second renderer, renders the same GI image (the
// description holds everything the pass sees). User: a scene built as a program would (a sphere on a
// dataset-mapped ground, a scalar-coloured surface, a headlight, a light kit's
// camera light, a text overlay) is written with notes for the headlight, the camera light and
// the overlay, and reads back to the same image. Refused: a scene using what Cycles cannot
// match is refused with every use named, and no file is written. Damaged: OBJ and JSON files
// with indices beyond the points, tokens that are not numbers, fields of the wrong type or
// missing files are refused with one error each, and the renderer stays empty. Relative: an
// OBJ with relative indices and v/t/n corners reads as its absolute twin. Unwritable: names
// that cannot be written (a missing directory, /dev/full, a directory, "", an .obj name) give
// false, one error and no file. NonFinite: NaN points, light values, camera and material are
// refused with each named. Empty: actors without polygons are left out with a note and no
// error.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGISceneFile.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCellArray.h"
#include "vtkActor2DCollection.h"
#include "vtkCamera.h"
#include "vtkDataSetMapper.h"
#include "vtkElevationFilter.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3DMapper.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLineSource.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkTexture.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace
{
// The pass's composite of `renderer` at 64^3 voxels, 200 x 200 pixels, or VTK's own image.
vtkSmartPointer<vtkFloatArray> Image(vtkRenderer* renderer, bool withGI)
{
  voxelgi_test::GIWindow view(renderer, 64, 200, 0);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  auto pixels = vtkSmartPointer<vtkFloatArray>::New();
  if (!withGI)
  {
    renderer->SetPass(nullptr); // VTK's own image (the renderer outlives this window)
    window->Render();
    window->GetRGBAPixelData(0, 0, 199, 199, 0, pixels);
    return pixels;
  }
  window->Render();
  if (!gi->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, pixels))
  {
    return nullptr;
  }
  renderer->SetPass(nullptr);
  gi->ReleaseGraphicsResources(window);
  return pixels;
}

std::string Prefix(const std::string& name)
{
  const std::string dir = "Testing/Temporary";
  vtksys::SystemTools::MakeDirectory(dir);
  return dir + "/TestSceneFile-" + name;
}

// Writes `original` (which the test then renders), reads it into a new renderer and compares
// the two images (GI, or VTK's own): the mean and largest channel difference relative to the
// image's mean.
int RoundTrip(vtkRenderer* original, const std::string& name, const std::string& notes,
  bool withGI)
{
  vtkNew<vtkVoxelGISceneFile> file;
  file->SetFileName((Prefix(name) + ".json").c_str());
  file->SetSize(200, 200);
  VOXELGI_CHECK(file->Write(original), file->GetProblems());
  std::cout << "notes:\n" << file->GetNotes();
  VOXELGI_CHECK(std::string(file->GetNotes()) == notes, "notes expected:\n" << notes);
  vtkNew<vtkRenderer> copy;
  vtkNew<vtkVoxelGISceneFile> reader;
  reader->SetFileName(file->GetFileName());
  VOXELGI_CHECK(reader->Read(copy), "cannot read it back");
  VOXELGI_CHECK(reader->GetSize()[0] == 200 && reader->GetSize()[1] == 200, "size");
  VOXELGI_CHECK(copy->GetActors()->GetNumberOfItems() > 0, "no actors read");
  // Lights that follow the camera follow it again (the error study orbits with them).
  auto lightTypes = [](vtkRenderer* r) {
    std::string types;
    vtkCollectionSimpleIterator it;
    r->GetLights()->InitTraversal(it);
    while (vtkLight* light = r->GetLights()->GetNextLight(it))
    {
      types += std::to_string(light->GetLightType());
    }
    return types;
  };
  VOXELGI_CHECK(lightTypes(copy) == lightTypes(original),
    "light types " << lightTypes(copy) << ", written " << lightTypes(original));

  // The description leaves overlays out, and so does the comparison.
  while (original->GetActors2D()->GetNumberOfItems() > 0)
  {
    original->RemoveActor2D(original->GetActors2D()->GetLastActor2D());
  }
  vtkSmartPointer<vtkFloatArray> a = Image(original, withGI);
  vtkSmartPointer<vtkFloatArray> b = Image(copy, withGI);
  VOXELGI_CHECK(a && b, "no image");
  double mean = 0.0, diff = 0.0, largest = 0.0;
  const vtkIdType n = a->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double d = std::abs(a->GetComponent(i, c) - b->GetComponent(i, c));
      mean += a->GetComponent(i, c);
      diff += d;
      largest = std::max(largest, d);
    }
  }
  mean /= 3.0 * n;
  diff /= 3.0 * n;
  std::cout << name << ": image mean " << mean << ", mean difference " << diff / mean
            << " of it, largest " << largest / mean << std::endl;
  VOXELGI_CHECK(mean > 0.01, "a dark image compares nothing");
  // Only edge pixels may differ (float rounding of positions written with 9 digits).
  VOXELGI_CHECK(diff < 0.002 * mean, "the images differ");
  return EXIT_SUCCESS;
}

int UserScene()
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.0, 0.6, 0.0);
  sphere->SetRadius(0.6);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  vtkNew<vtkElevationFilter> height;
  height->SetInputConnection(sphere->GetOutputPort());
  height->SetLowPoint(0.0, 0.0, 0.0);
  height->SetHighPoint(0.0, 1.2, 0.0);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(height->GetOutputPort());
  vtkNew<vtkActor> ball;
  ball->SetMapper(sphereMapper);
  ball->SetPosition(0.3, 0.0, 0.0); // an actor transform, baked into the description
  renderer->AddActor(ball);

  vtkNew<vtkImageData> ground; // a dataset, not polygons: the mapper extracts its surface
  ground->SetDimensions(11, 2, 11);
  ground->SetOrigin(-2.5, -0.2, -2.5);
  ground->SetSpacing(0.5, 0.2, 0.5);
  vtkNew<vtkDataSetMapper> groundMapper;
  groundMapper->SetInputData(ground);
  groundMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> floor;
  floor->SetMapper(groundMapper);
  floor->GetProperty()->SetColor(0.8, 0.75, 0.7);
  renderer->AddActor(floor);

  vtkNew<vtkTextActor> title;
  title->SetInput("overlay");
  renderer->AddActor2D(title);
  vtkNew<vtkLight> fill; // a camera light, as vtkLightKit makes them
  fill->SetLightTypeToCameraLight();
  fill->SetPosition(-1.0, 0.5, 1.0);
  fill->SetFocalPoint(0.0, 0.0, 0.0);
  fill->SetIntensity(0.4);
  renderer->AddLight(fill);
  vtkNew<vtkLight> head;
  head->SetLightTypeToHeadlight();
  head->SetIntensity(0.7);
  renderer->AddLight(head);

  renderer->GetActiveCamera()->SetPosition(2.0, 2.5, 4.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.4, 0.0);
  renderer->ResetCameraClippingRange();
  return RoundTrip(renderer, "User",
    "overlays (2D actors) are left out: Cycles renders the 3D scene only\n"
    "camera lights are written as scene lights for the current camera\n"
    "the headlight is written as a scene light for the current camera\n",
    // VTK's own image: the pass leaves dataset mappers out, the copy's polygons it would not
    false);
}

int Refused()
{
  vtkNew<vtkRenderer> renderer;
  auto add = [&renderer](vtkAlgorithm* source) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
    return actor.GetPointer();
  };
  vtkNew<vtkSphereSource> sphere;
  vtkProperty* glass = add(sphere)->GetProperty();
  glass->SetOpacity(0.5);
  glass->SetSpecular(0.5);
  add(sphere)->GetProperty()->SetRepresentationToWireframe();
  vtkNew<vtkTexture> texture;
  add(sphere)->SetTexture(texture);
  add(sphere)->GetProperty()->SetAmbient(0.3);
  vtkNew<vtkLineSource> line;
  add(line);
  vtkNew<vtkGlyph3DMapper> glyphs;
  glyphs->SetInputConnection(sphere->GetOutputPort());
  glyphs->SetSourceConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> glyphActor;
  glyphActor->SetMapper(glyphs);
  renderer->AddActor(glyphActor);
  vtkNew<vtkVolume> volume;
  renderer->AddVolume(volume);
  vtkNew<vtkLight> spot;
  spot->SetPositional(true);
  spot->SetConeAngle(30.0);
  renderer->AddLight(spot);
  vtkNew<vtkLight> attenuated;
  attenuated->SetPositional(true);
  attenuated->SetConeAngle(90.0);
  attenuated->SetAttenuationValues(1.0, 0.5, 0.0);
  renderer->AddLight(attenuated);
  renderer->GetActiveCamera()->ParallelProjectionOn();
  renderer->GradientBackgroundOn();

  vtkNew<vtkVoxelGISceneFile> file;
  const std::string json = Prefix("Refused") + ".json";
  vtksys::SystemTools::RemoveFile(json);
  file->SetFileName(json.c_str());
  file->GlobalWarningDisplayOff(); // the one error is expected; its text is checked below
  VOXELGI_CHECK(!file->Write(renderer), "written");
  const std::string problems = file->GetProblems();
  std::cout << "problems:\n" << problems;
  for (const char* expected : { "prop 0 (vtkOpenGLActor): translucent (opacity 0.500000) with scalar colours, emission or a specular term",
         "prop 1 (vtkOpenGLActor): wireframe or points representation", "prop 2 (vtkOpenGLActor): textured",
         "prop 3 (vtkOpenGLActor): ambient term that is not the background's sky light",
         "prop 4 (vtkOpenGLActor): lines or vertices", "prop 5 (vtkOpenGLActor): mapper vtkOpenGLGlyph3DMapper",
         "prop 6 (vtkVolume): a volume other than axis-aligned image data", "light 0: spot light",
         "light 1: attenuated point light", "camera: parallel projection",
         "background: gradient or textured" })
  {
    VOXELGI_CHECK(problems.find(expected) != std::string::npos, "not named: " << expected);
  }
  VOXELGI_CHECK(std::count(problems.begin(), problems.end(), '\n') == 11, "one line each");
  VOXELGI_CHECK(!vtksys::SystemTools::FileExists(json), "a refused scene was written");
  return EXIT_SUCCESS;
}

// A sphere on a plane under one point light of intensity 0.8: the scene the damage cases start
// from.
void SmallScene(vtkRenderer* renderer)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.0, 0.5, 0.0);
  sphere->SetRadius(0.5);
  vtkVoxelGIScenes::AddSource(renderer, sphere, 0.8, 0.4, 0.2);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-2.0, 0.0, -2.0);
  plane->SetPoint1(-2.0, 0.0, 2.0);
  plane->SetPoint2(2.0, 0.0, -2.0);
  vtkVoxelGIScenes::AddSource(renderer, plane, 0.7, 0.7, 0.7);
  vtkNew<vtkLight> light;
  light->SetPositional(true);
  light->SetConeAngle(90.0);
  light->SetPosition(1.0, 3.0, 1.0);
  light->SetIntensity(0.8);
  renderer->AddLight(light);
  renderer->GetActiveCamera()->SetPosition(0.0, 2.0, 5.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.3, 0.0);
}

std::string Slurp(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string Replaced(std::string text, const std::string& from, const std::string& to)
{
  const size_t at = text.find(from);
  if (at == std::string::npos)
  {
    std::cerr << "FAILED: the written file lacks " << from << std::endl;
    std::exit(EXIT_FAILURE);
  }
  return text.replace(at, from.size(), to);
}

// Read() of `json` fails with one error that contains `part`, and adds nothing.
int ReadFails(const std::string& json, const std::string& part)
{
  vtkNew<vtkRenderer> renderer;
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkVoxelGISceneFile> file;
  voxelgi_test::Messages messages(file);
  file->SetFileName(json.c_str());
  VOXELGI_CHECK(!file->Read(renderer), json << " was read");
  VOXELGI_CHECK(messages.Count == 1, messages.Count << " messages: " << messages.Text);
  VOXELGI_CHECK(messages.Has(part), "the error does not say " << part << ": " << messages.Text);
  VOXELGI_CHECK(renderer->GetActors()->GetNumberOfItems() == 0 &&
      renderer->GetLights()->GetNumberOfItems() == 0,
    "a damaged file changed the renderer");
  return EXIT_SUCCESS;
}

int Damaged()
{
  vtkNew<vtkRenderer> renderer;
  SmallScene(renderer);
  vtkNew<vtkVoxelGISceneFile> file;
  const std::string stem = Prefix("Damaged");
  file->SetFileName((stem + ".json").c_str());
  VOXELGI_CHECK(file->Write(renderer), file->GetProblems());
  const std::string json = Slurp(stem + ".json"), obj = Slurp(stem + ".obj");
  const std::string objName = "\"TestSceneFile-Damaged.obj\"";
  struct Damage
  {
    std::string Obj, Json, Error;
  };
  const Damage cases[] = {
    { obj + "f 1 2 99999\n", json, "index \"99999\" names none" },
    { obj + "f 1 x 3\n", json, "index \"x\"" },
    { obj + "f -1 -2 -99999\n", json, "index \"-99999\"" },
    { obj + "f 0 1 2\n", json, "index \"0\"" },
    { obj + "f 1 2\n", json, "a face needs 3 corners" },
    { obj + "v 1 abc 2\n", json, "\"abc\" is not a finite number" },
    { obj + "v 1 nan 2\n", json, "\"nan\" is not a finite number" },
    { obj + "usemtl other\nf 1 2 3\n", json, "materials has no \"other\"" },
    { "f 1 2 3\n" + obj, json, "a face needs 3 corners and a material" },
    { obj, Replaced(json, "\"intensity\" : 0.8", "\"intensity\" : \"bright\""),
      "lights[0].intensity is not a finite number" },
    { obj, Replaced(json, "\"view_angle\" : 30.0", "\"view_angle\" : null"),
      "camera.view_angle is not a finite number" },
    { obj, Replaced(json, "\"ambient\" : 0.0", "\"ambient\" : [ 1 ]"),
      "materials.actor0.vtk.ambient is not a finite number" },
    { obj, Replaced(json, "\"normals\" : \"point\"", "\"normals\" : 3"),
      "materials.actor0.normals is not a string" },
    { obj, Replaced(json, "\"lights\" : ", "\"lights\" : {}, \"unused\" : "),
      "lights is not a list" },
    { obj, Replaced(json, "\"camera\" : ", "\"unused\" : "), "has no \"camera\"" },
    { obj, Replaced(json, objName, "\"TestSceneFile-Missing.obj\""), "cannot open" },
    { obj, json.substr(0, json.size() / 2), "not a JSON file" },
  };
  int index = 0;
  for (const Damage& damage : cases)
  {
    // each in a directory of its own, where the description names its OBJ file as written
    const std::string dir = stem + "-" + std::to_string(index++);
    vtksys::SystemTools::MakeDirectory(dir);
    const std::string name = dir + "/TestSceneFile-Damaged";
    std::ofstream(name + ".obj") << damage.Obj;
    std::ofstream(name + ".json") << damage.Json;
    if (ReadFails(name + ".json", damage.Error) != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
  }
  return ReadFails(stem + "-none.json", "not a JSON file");
}

int Relative()
{
  const std::string stem = Prefix("Relative");
  std::ofstream(stem + ".obj") << "mtllib TestSceneFile-Relative.mtl\nusemtl a\n"
                                  "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\n"
                                  "f -3//-1 -2//-1 -1//-1\n"
                                  "v 0 0 1\nv 1 0 1\nv 0 1 1\nvt 0 0\n"
                                  "f 4/1/1 5/1/1 -1/1/-1\n";
  std::ofstream(stem + ".json")
    << R"({ "obj" : "TestSceneFile-Relative.obj", "size" : [ 64, 48 ], "background" : [ 0, 0, 0 ],
  "camera" : { "position" : [ 0, 0, 5 ], "focal_point" : [ 0, 0, 0 ], "view_up" : [ 0, 1, 0 ],
               "view_angle" : 30 },
  "lights" : [ { "type" : "directional", "direction" : [ 0, 0, -1 ], "color" : [ 1, 1, 1 ],
                 "intensity" : 1 } ],
  "materials" : { "a" : { "normals" : "point", "vtk" : { "ambient" : 0, "ambient_color" : [ 1, 1, 1 ],
    "diffuse" : 1, "diffuse_color" : [ 0.5, 0.5, 0.5 ], "specular" : 0,
    "specular_color" : [ 1, 1, 1 ], "specular_power" : 1 } } } })";
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkVoxelGISceneFile> file;
  file->SetFileName((stem + ".json").c_str());
  VOXELGI_CHECK(file->Read(renderer), "not read");
  VOXELGI_CHECK(file->GetSize()[0] == 64 && file->GetSize()[1] == 48, "size");
  VOXELGI_CHECK(renderer->GetActors()->GetNumberOfItems() == 1, "one actor");
  auto* pd = vtkPolyData::SafeDownCast(
    renderer->GetActors()->GetLastActor()->GetMapper()->GetInputDataObject(0, 0));
  VOXELGI_CHECK(pd->GetNumberOfPoints() == 6 && pd->GetNumberOfPolys() == 2, "counts");
  // Relative indices name the points defined before them, in the order written.
  const double expected[6][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 1, 0, 1 }, { 0, 1, 1 } };
  for (vtkIdType i = 0; i < 6; ++i)
  {
    double x[3];
    pd->GetPoint(i, x);
    VOXELGI_CHECK(x[0] == expected[i][0] && x[1] == expected[i][1] && x[2] == expected[i][2],
      "point " << i);
  }
  vtkNew<vtkIdList> ids;
  pd->GetCellPoints(1, ids);
  VOXELGI_CHECK(ids->GetNumberOfIds() == 3 && ids->GetId(0) == 3 && ids->GetId(2) == 5, "cell 1");
  VOXELGI_CHECK(pd->GetPointData()->GetNormals()->GetComponent(5, 2) == 1.0, "normals");
  return EXIT_SUCCESS;
}

int Unwritable()
{
  vtkNew<vtkRenderer> renderer;
  SmallScene(renderer);
  const std::string missing = Prefix("no-such-directory") + "/scene.json";
  std::vector<std::string> names = { missing, "Testing/Temporary", "", Prefix("x") + ".obj" };
  if (vtksys::SystemTools::FileExists("/dev/full"))
  {
    names.push_back("/dev/full");
  }
  for (const std::string& name : names)
  {
    vtkNew<vtkVoxelGISceneFile> file;
    voxelgi_test::Messages messages(file);
    file->SetFileName(name.c_str());
    VOXELGI_CHECK(!file->Write(renderer), "\"" << name << "\" written");
      VOXELGI_CHECK(messages.Count == 1, messages.Count << " messages for \"" << name << "\"");
  }
  for (const std::string& left :
    { Prefix("x") + ".mtl", std::string("/dev/full.obj"), std::string("/dev/full.mtl") })
  {
    VOXELGI_CHECK(!vtksys::SystemTools::FileExists(left), left << " was left");
  }
  return EXIT_SUCCESS;
}

int NonFinite()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vtkNew<vtkRenderer> renderer;
  SmallScene(renderer);
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.0, 0.0, 0.0);
  points->InsertNextPoint(1.0, nan, 0.0);
  points->InsertNextPoint(0.0, 1.0, 0.0);
  vtkNew<vtkCellArray> triangle;
  const vtkIdType ids[] = { 0, 1, 2 };
  triangle->InsertNextCell(3, ids);
  vtkNew<vtkPolyData> broken;
  broken->SetPoints(points);
  broken->SetPolys(triangle);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(broken);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor); // prop 2
  vtkNew<vtkSphereSource> sphere;
  vtkVoxelGIScenes::AddSource(renderer, sphere, nan, 0.5, 0.5); // prop 3
  vtkNew<vtkLight> moved;
  moved->SetPosition(nan, 1.0, 1.0);
  renderer->AddLight(moved); // light 1
  vtkNew<vtkLight> dimmed;
  dimmed->SetIntensity(nan);
  renderer->AddLight(dimmed); // light 2
  renderer->GetActiveCamera()->SetViewAngle(nan);

  vtkNew<vtkVoxelGISceneFile> file;
  voxelgi_test::Messages messages(file);
  const std::string json = Prefix("NonFinite") + ".json";
  vtksys::SystemTools::RemoveFile(json);
  file->SetFileName(json.c_str());
  VOXELGI_CHECK(!file->Write(renderer), "written");
  const std::string problems = file->GetProblems();
  std::cout << problems;
  for (const char* expected : { "prop 2 (vtkOpenGLActor): non-finite point coordinates",
         "prop 3 (vtkOpenGLActor): non-finite material values", "light 1: non-finite",
         "light 2: non-finite", "camera: non-finite" })
  {
    VOXELGI_CHECK(problems.find(expected) != std::string::npos, "not named: " << expected);
  }
  VOXELGI_CHECK(std::count(problems.begin(), problems.end(), '\n') == 5, "one line each");
  VOXELGI_CHECK(messages.Count == 1, messages.Count << " messages");
  VOXELGI_CHECK(!vtksys::SystemTools::FileExists(json), "a refused scene was written");
  return EXIT_SUCCESS;
}

int Empty()
{
  vtkNew<vtkRenderer> renderer;
  SmallScene(renderer);
  vtkNew<vtkPolyData> nothing;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.0, 0.0, 0.0);
  vtkNew<vtkPolyData> pointsOnly; // points but no cells: VTK draws nothing either
  pointsOnly->SetPoints(points);
  for (vtkPolyData* data : { nothing.GetPointer(), pointsOnly.GetPointer() })
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(data);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
  }
  vtkNew<vtkVoxelGISceneFile> file;
  voxelgi_test::Messages messages(file);
  file->SetFileName((Prefix("Empty") + ".json").c_str());
  VOXELGI_CHECK(file->Write(renderer), file->GetProblems());
  VOXELGI_CHECK(messages.Count == 0, "messages: " << messages.Text);
  VOXELGI_CHECK(std::string(file->GetNotes()) == "actors without polygons are left out\n",
    "notes: " << file->GetNotes());
  vtkNew<vtkRenderer> copy;
  vtkNew<vtkVoxelGISceneFile> reader;
  reader->SetFileName(file->GetFileName());
  VOXELGI_CHECK(reader->Read(copy), "not read back");
  VOXELGI_CHECK(copy->GetActors()->GetNumberOfItems() == 2, "the sphere and the plane");
  return EXIT_SUCCESS;
}
}

int TestSceneFile(int argc, char* argv[])
{
  const std::string which = argc > 1 ? argv[1] : "cornell";
  const std::map<std::string, int (*)()> cases = { { "User", UserScene }, { "Refused", Refused },
    { "Damaged", Damaged }, { "Relative", Relative }, { "Unwritable", Unwritable },
    { "NonFinite", NonFinite }, { "Empty", Empty } };
  const auto found = cases.find(which);
  if (found != cases.end())
  {
    return found->second();
  }
  vtkNew<vtkRenderer> renderer;
  VOXELGI_CHECK(vtkVoxelGIScenes::AddScene(renderer, which.c_str()), "unknown case " << which);
  // Only the scene under VTK's headlight has something to say.
  return RoundTrip(renderer, which,
    which == "contactsheadlight"
      ? "the headlight is written as a scene light for the current camera\n"
      : "",
    true);
}
