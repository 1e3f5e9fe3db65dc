// The scene description of the error study (vtkVoxelGISceneFile), one case per run:
//
//   TestSceneFile CASE     (CTest runs each as VoxelGI::SceneFile.CASE)
//
// SCENE (cornell, glossy, isosurface, glyphs, emissive, streamlines): the built-in scene,
// written and read back into a second renderer, renders the same GI image (the description
// holds everything the pass sees). User: a scene built as a program would (a sphere on a
// dataset-mapped ground, a scalar-coloured surface, a headlight, a light kit's
// camera light, a text overlay) is written with notes for the headlight, the camera light and
// the overlay, and reads back to the same image. Refused: a scene using what Cycles cannot
// match is refused with every use named, and no file is written.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGISceneFile.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkActor2DCollection.h"
#include "vtkCamera.h"
#include "vtkDataSetMapper.h"
#include "vtkElevationFilter.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLineSource.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
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
#include <iostream>
#include <string>

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
  add(sphere)->GetProperty()->SetOpacity(0.5);
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
  for (const char* expected : { "prop 0 (vtkOpenGLActor): translucent",
         "prop 1 (vtkOpenGLActor): wireframe or points representation", "prop 2 (vtkOpenGLActor): textured",
         "prop 3 (vtkOpenGLActor): ambient term that is not the background's sky light",
         "prop 4 (vtkOpenGLActor): lines or vertices", "prop 5 (vtkOpenGLActor): mapper vtkOpenGLGlyph3DMapper",
         "prop 6 (vtkVolume): not an actor", "light 0: spot light",
         "light 1: attenuated point light", "camera: parallel projection",
         "background: gradient or textured" })
  {
    VOXELGI_CHECK(problems.find(expected) != std::string::npos, "not named: " << expected);
  }
  VOXELGI_CHECK(std::count(problems.begin(), problems.end(), '\n') == 11, "one line each");
  VOXELGI_CHECK(!vtksys::SystemTools::FileExists(json), "a refused scene was written");
  return EXIT_SUCCESS;
}
}

int TestSceneFile(int argc, char* argv[])
{
  const std::string which = argc > 1 ? argv[1] : "cornell";
  if (which == "User")
  {
    return UserScene();
  }
  if (which == "Refused")
  {
    return Refused();
  }
  vtkNew<vtkRenderer> renderer;
  VOXELGI_CHECK(vtkVoxelGIScenes::AddScene(renderer, which.c_str()), "unknown case " << which);
  return RoundTrip(renderer, which, "", true);
}
