// Leave out what the scene does not need: for each kind of change, two frames are rendered
// and exactly the expected stages must run on the second; the image must then equal a full
// recompute by a fresh pass. Also the update policies and the memory of unneeded volumes.
// Overlays that VTK redraws every frame (text, scalar bar, cube axes, legend: their
// modification times change while they render) are in the scene and must not make an
// unchanged frame re-trace. Changes that neither the actor nor its mapper record must still
// be seen: a clipping plane moved, a texture's image, a shader uniform, a glyph mapper's
// source (glyphs are voxelized), an image actor's image, a light beyond the light block's 16.
// A headlight relights the voxels only after turning by more than CameraLightTurn.
// A source two steps up an actor's pipeline changed: the scan reads what VTK's frustum
// culler already updated this frame, and updates the pipeline itself without that culler.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeAxesActor.h"
#include "vtkCubeSource.h"
#include "vtkCuller.h"
#include "vtkCullerCollection.h"
#include "vtkElevationFilter.h"
#include "vtkLegendBoxActor.h"
#include "vtkLookupTable.h"
#include "vtkScalarBarActor.h"
#include "vtkTextActor.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageMapper3D.h"
#include "vtkMapper.h"
#include "vtkPlane.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkShaderProperty.h"
#include "vtkTexture.h"
#include "vtkUniforms.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <functional>
#include <string>

namespace
{
using voxelgi_test::StagesRan;

const std::string Trace = "GBuffer,ConeTrace,Composite,Present";
const std::string Light = "LightVoxels,Mipmap,Bounce," + Trace;
// The directional scene light has a shadow map (LightOcclusion ShadowMaps): a relight redraws
// it when the light turned or what it sees changed.
const std::string Relight = "ShadowMaps," + Light;
// A headlight's relight (no shadow map: what it lights hides its shadows): one bounce
// continues from the last solution.
const std::string Follow = Light;
const std::string Full = "Scan,Clear,VoxelizeStatic,VoxelizeDynamic,Resolve," + Relight;

// Largest difference between the pass's composite and a full recompute by a fresh pass.
double DifferenceFromFullRecompute(vtkRenderer* renderer, vtkRenderWindow* window, vtkVoxelGIPass* gi)
{
  vtkNew<vtkFloatArray> incremental;
  gi->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, incremental);
  vtkNew<vtkVoxelGIPass> fresh;
  fresh->SetSoftwareProfileToOff();
  fresh->SetVoxelResolution(gi->GetVoxelResolution());
  renderer->SetPass(fresh);
  window->Render();
  vtkNew<vtkFloatArray> full;
  fresh->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, full);
  renderer->SetPass(gi);
  fresh->ReleaseGraphicsResources(window);
  if (full->GetNumberOfValues() != incremental->GetNumberOfValues() || full->GetNumberOfValues() == 0)
  {
    return 1e30;
  }
  double worst = 0.0;
  for (vtkIdType i = 0; i < full->GetNumberOfValues(); ++i)
  {
    worst = std::max(worst, static_cast<double>(std::abs(full->GetValue(i) - incremental->GetValue(i))));
  }
  return worst;
}
}

int TestStageSkipping(int, char*[])
{
  vtkNew<vtkRenderer> renderer;
  using glm::dvec3;
  voxelgi_test::AddQuad(renderer, dvec3(-3, 0, -3), dvec3(-3, 0, 3), dvec3(3, 0, -3), 0.8, 0.8, 0.8);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(-1.0, 0.8, 0.0);
  sphere->SetRadius(0.8);
  vtkActor* ball = vtkVoxelGIScenes::AddSource(renderer, sphere, 0.9, 0.5, 0.2);
  // Clipped by a plane that first keeps all of it; tinted by a custom shader uniform.
  vtkNew<vtkPlane> clip;
  clip->SetOrigin(0.0, -5.0, 0.0);
  clip->SetNormal(0.0, 1.0, 0.0);
  ball->GetMapper()->AddClippingPlane(clip);
  ball->GetShaderProperty()->AddFragmentShaderReplacement("//VTK::Color::Impl", true,
    "//VTK::Color::Impl\n  diffuseColor *= tint;\n", false);
  ball->GetShaderProperty()->GetFragmentCustomUniforms()->SetUniform3f("tint", std::array<float, 3>{ 1.f, 1.f, 1.f }.data());
  // A textured panel.
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 4, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (int i = 0; i < 16; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      image->GetPointData()->GetScalars()->SetComponent(i, c, ((i + i / 4) % 2) ? 220 : 40 * c);
    }
  }
  vtkNew<vtkTexture> texture;
  texture->SetInputData(image);
  vtkNew<vtkPlaneSource> panelSource;
  panelSource->SetOrigin(-2.5, 0.0, -2.5);
  panelSource->SetPoint1(-1.5, 0.0, -2.5);
  panelSource->SetPoint2(-2.5, 1.0, -2.5);
  vtkActor* panel = vtkVoxelGIScenes::AddSource(renderer, panelSource, 1.0, 1.0, 1.0);
  panel->SetTexture(texture);
  // Glyphs (voxelized, every instance) and an image slice (voxelized as a textured quad).
  vtkNew<vtkPoints> glyphPoints;
  glyphPoints->InsertNextPoint(2.0, 0.2, 2.0);
  glyphPoints->InsertNextPoint(2.5, 0.2, 2.0);
  vtkNew<vtkPolyData> glyphCentres;
  glyphCentres->SetPoints(glyphPoints);
  vtkNew<vtkCubeSource> glyphSource;
  glyphSource->SetXLength(0.3);
  vtkNew<vtkGlyph3DMapper> glyphMapper;
  glyphMapper->SetInputData(glyphCentres);
  glyphMapper->SetSourceConnection(glyphSource->GetOutputPort());
  vtkNew<vtkActor> glyphs;
  glyphs->SetMapper(glyphMapper);
  renderer->AddActor(glyphs);
  vtkNew<vtkImageData> slice;
  slice->SetDimensions(4, 4, 1);
  slice->SetSpacing(0.2, 0.2, 1.0);
  slice->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  slice->GetPointData()->GetScalars()->Fill(128);
  vtkNew<vtkImageActor> sliceActor;
  sliceActor->GetMapper()->SetInputData(slice);
  sliceActor->SetPosition(1.8, 0.5, -2.5); // clear of the floor: no voxels shared
  renderer->AddActor(sliceActor);
  // Floating clear of everything (no voxels shared), its geometry through a filter.
  vtkNew<vtkSphereSource> floatingSource;
  floatingSource->SetCenter(0.0, 1.3, -1.5);
  floatingSource->SetRadius(0.2);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(floatingSource->GetOutputPort());
  vtkActor* floating = vtkVoxelGIScenes::AddSource(renderer, elevation, 0.3, 0.8, 0.3);
  floating->GetMapper()->ScalarVisibilityOff();
  vtkNew<vtkCubeSource> cubeSource;
  cubeSource->SetBounds(0.5, 1.5, 0.0, 1.0, -0.5, 0.5);
  vtkActor* cube = vtkVoxelGIScenes::AddSource(renderer, cubeSource, 0.2, 0.4, 0.9);
  vtkVoxelGIPass::SetPropDynamic(cube, true);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(1.0, 4.0, 2.0);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(light);
  renderer->GetActiveCamera()->SetPosition(0.0, 3.0, 7.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.5, 0.0);

  vtkNew<vtkTextActor> text;
  text->SetInput("stage skipping");
  renderer->AddActor2D(text);
  vtkNew<vtkLookupTable> lut;
  lut->Build();
  vtkNew<vtkScalarBarActor> scalarBar;
  scalarBar->SetLookupTable(lut);
  renderer->AddActor2D(scalarBar);
  vtkNew<vtkCubeAxesActor> axes;
  axes->SetBounds(-3.0, 3.0, 0.0, 1.6, -3.0, 3.0);
  axes->SetCamera(renderer->GetActiveCamera());
  renderer->AddActor(axes);
  vtkNew<vtkLegendBoxActor> legend;
  legend->SetNumberOfEntries(1);
  sphere->Update();
  double red[3] = { 1.0, 0.0, 0.0 };
  legend->SetEntry(0, sphere->GetOutput(), "sphere", red);
  renderer->AddActor2D(legend);

  voxelgi_test::GIWindow view(renderer, 32, 100);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  // Skipping must be exact; temporal reuse is not (TestGITemporalReuse bounds it).
  gi->TemporalReuseOff();
  renderer->ResetCameraClippingRange();

  window->Render();
  VOXELGI_CHECK(StagesRan(gi) == Full, "first frame ran " << StagesRan(gi));

  struct Case
  {
    const char* Name;
    std::function<void()> Change;
    std::string Expected;
    double Tolerance = 1e-4; // largest difference from a full recompute
  };
  const Case cases[] = {
    { "nothing changed", [] {}, "Scan,Present" },
    { "camera moved", [&] { renderer->GetActiveCamera()->Azimuth(10.0); }, "Scan," + Trace },
    { "light changed", [&] { light->SetIntensity(0.7); }, "Scan," + Light }, // the map kept
    { "light moved", [&] { light->SetPosition(1.5, 4.0, 2.0); }, "Scan," + Relight },
    { "dynamic actor moved", [&] { cube->AddPosition(0.0, 0.0, 1.0); },
      "Scan,Clear,VoxelizeDynamic,Resolve," + Relight },
    { "bounds grew beyond the grid", [&] { cube->AddPosition(5.0, 0.0, 0.0); }, Full },
    // Actors change where neither they nor their mappers record it.
    { "clipping plane moved", [&] { clip->SetOrigin(0.0, 0.8, 0.0); }, Full },
    { "shader uniform changed",
      [&] {
        ball->GetShaderProperty()->GetFragmentCustomUniforms()->SetUniform3f(
          "tint", std::array<float, 3>{ 0.2f, 1.f, 0.2f }.data());
      },
      "Scan,Clear,VoxelizeDynamic,Resolve," + Relight }, // the ball is dynamic since the clip
    { "image slice changed",
      [&] {
        slice->GetPointData()->GetScalars()->Fill(30);
        slice->Modified();
      },
      Full },
    { "a source upstream of a filter changed", [&] { floatingSource->SetCenter(0.4, 1.3, -1.5); },
      Full },
    { "sixteen more lights",
      [&] {
        for (int l = 0; l < 16; ++l)
        {
          vtkNew<vtkLight> weak;
          weak->SetLightTypeToSceneLight();
          weak->SetPosition(-2.0 + 0.25 * l, 3.0, 2.0);
          weak->SetFocalPoint(0.0, 0.0, 0.0);
          weak->SetIntensity(0.02);
          renderer->AddLight(weak);
        }
      },
      "Scan," + Relight },
    // The light block holds 16 lights; VTK shades with the 17th too.
    { "the 17th light changed",
      [&] { vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(16))->SetIntensity(0.5); },
      "Scan," + Trace },
    // While VTK renders interactively (an interactor style's update rate while a mouse button
    // is down: InteractiveBounces), a moved light relights with one bounce on from the last
    // solution; the first still frame bounces them all and equals a full recompute.
    { "a light dragged interactively",
      [&] {
        window->SetDesiredUpdateRate(15.0);
        light->SetPosition(1.0, 4.0, 1.0);
      },
      "Scan," + Relight, 0.05 },
    { "the still frame after it", [&] { window->SetDesiredUpdateRate(0.0001); }, "Scan," + Light },
    // Last: from here on scattered pixels differ from a fresh pass by one half-float step of
    // the indirect light (2.4e-4), also after a forced full rebuild; stale voxels differ by
    // far more. The changed panel also turns dynamic and leaves the voxels it shares with the
    // floor to it (as the glyphs below): in the window's multisampled edge pixels where the
    // panel meets the floor that shows, up to 2.7e-3.
    { "texture image changed",
      [&] {
        image->GetPointData()->GetScalars()->Fill(250);
        image->Modified();
      },
      Full, 4e-3 },
    // Same bounds, so the grid stays. The changed glyph actor turns dynamic, and a dynamic
    // prop leaves the voxels it shares with static ones (the floor under the glyphs) to
    // them, where a fresh pass, to which the glyphs are static, averages both colours: the
    // image within 0.0036 (a stale glyph would differ by its whole light).
    { "glyph source changed", [&] { glyphSource->SetXLength(0.2); }, Full, 4e-3 },
  };
  for (const Case& c : cases)
  {
    window->Render(); // settle
    c.Change();
    renderer->ResetCameraClippingRange();
    window->Render();
    std::cout << c.Name << ": " << StagesRan(gi) << std::endl;
    VOXELGI_CHECK(StagesRan(gi) == c.Expected, c.Name << " ran " << StagesRan(gi) << ", expected " << c.Expected);
    const double difference = DifferenceFromFullRecompute(renderer, window, gi);
    std::cout << "  largest difference from a full recompute: " << difference << std::endl;
    VOXELGI_CHECK(difference < c.Tolerance, c.Name << ": skipping changed the image");
  }

  // Without VTK's frustum culler nothing updated the pipelines before the pass.
  vtkSmartPointer<vtkCuller> culler = renderer->GetCullers()->GetLastItem();
  renderer->GetCullers()->RemoveAllItems();
  window->Render();
  floatingSource->SetCenter(0.0, 1.3, -1.5);
  window->Render();
  VOXELGI_CHECK(StagesRan(gi) == "Scan,Clear,VoxelizeDynamic,Resolve," + Relight,
    "without a culler, an upstream change ran " << StagesRan(gi));
  const double unculled = DifferenceFromFullRecompute(renderer, window, gi);
  std::cout << "  without a culler: largest difference from a full recompute: " << unculled
            << std::endl;
  VOXELGI_CHECK(unculled < 4e-3, "without a culler, an upstream change was missed");
  renderer->GetCullers()->AddItem(culler);

  // Camera-following lights: the scene's lights off, a headlight on. Turns below
  // CameraLightTurn keep the voxel light; beyond it the voxels are relit and bounced.
  vtkCollectionSimpleIterator lit;
  renderer->GetLights()->InitTraversal(lit);
  while (vtkLight* sceneLight = renderer->GetLights()->GetNextLight(lit))
  {
    sceneLight->SwitchOff();
  }
  vtkNew<vtkLight> headlight;
  headlight->SetLightTypeToHeadlight();
  renderer->AddLight(headlight);
  gi->SetCameraLightTurn(15.0);
  window->Render();
  vtkCamera* camera = renderer->GetActiveCamera();
  const std::pair<std::function<void()>, std::string> turns[] = {
    { [&] { camera->Azimuth(10.0); }, "Scan," + Trace },
    { [&] { camera->Azimuth(-4.0); }, "Scan," + Trace },  // 6 degrees from the lit direction
    { [&] { camera->Azimuth(10.0); }, "Scan," + Follow }, // 16
    { [&] { camera->Dolly(1.2); }, "Scan," + Trace }, // a directional light does not turn
    { [&] { camera->Elevation(14.0); }, "Scan," + Trace },
    { [&] { gi->SetCameraLightTurn(0.0); }, "Scan," + Trace }, // a setting: re-traced
    { [&] { camera->Azimuth(1.0); }, "Scan," + Follow },
  };
  for (const auto& turn : turns)
  {
    turn.first();
    renderer->ResetCameraClippingRange();
    window->Render();
    std::cout << "headlight: " << StagesRan(gi) << std::endl;
    VOXELGI_CHECK(StagesRan(gi) == turn.second, "a headlight change ran " << StagesRan(gi) << ", expected " << turn.second);
  }
  // The continued solution against a converged one.
  const double followed = DifferenceFromFullRecompute(renderer, window, gi);
  std::cout << "  followed: largest difference from a full recompute: " << followed << std::endl;
  VOXELGI_CHECK(followed < 0.02, "a camera light's relight differs from a full recompute");
  headlight->SetIntensity(0.8); // not only turned: everything relit
  window->Render();
  VOXELGI_CHECK(StagesRan(gi) == "Scan," + Light, "a headlight's intensity ran " << StagesRan(gi));
  // Within the glyph case's bound (the glyphs stay dynamic).
  const double relit = DifferenceFromFullRecompute(renderer, window, gi);
  std::cout << "  relit: largest difference from a full recompute: " << relit << std::endl;
  VOXELGI_CHECK(relit < 4e-3, "relit headlight differs from a full recompute");
  renderer->RemoveLight(headlight);
  light->SwitchOn();

  // Update policies.
  gi->SetUpdatePolicyToOnDemand();
  window->Render();
  cube->AddPosition(-1.0, 0.0, 0.0);
  window->Render();
  VOXELGI_CHECK(StagesRan(gi) == "Scan," + Trace, "on demand, a moved actor ran " << StagesRan(gi));
  gi->Invalidate();
  window->Render();
  VOXELGI_CHECK(StagesRan(gi) == Full, "after Invalidate() ran " << StagesRan(gi));

  gi->SetUpdatePolicyToEveryNFrames();
  gi->SetUpdateInterval(3);
  gi->Invalidate(); // an update now; the next may come three frames later
  window->Render();
  std::string voxelFrames;
  for (int frame = 0; frame < 6; ++frame)
  {
    cube->AddPosition(0.0, 0.0, 0.1);
    window->Render();
    voxelFrames += gi->GetStageRan(vtkVoxelGIPass::STAGE_VOXELIZE_DYNAMIC) ? "V" : ".";
  }
  VOXELGI_CHECK(voxelFrames == "..V..V", "every 3 frames voxelized as " << voxelFrames);

  gi->SetUpdatePolicyToEveryFrame();
  window->Render();
  window->Render();
  VOXELGI_CHECK(StagesRan(gi) == Full, "every frame, an unchanged frame ran " << StagesRan(gi));
  gi->SetUpdatePolicyToOnChange();

  // Memory of what the scene or the settings do not need is not allocated.
  VOXELGI_CHECK(gi->GetAllocatedBytes(vtkVoxelGIPass::RESOURCE_EMISSION) == 0, "emission allocated");
  VOXELGI_CHECK(gi->GetAllocatedBytes(vtkVoxelGIPass::RESOURCE_SHADOW_MAPS) > 0, "no shadow map");
  gi->SetLightOcclusionToVoxelShadows();
  window->Render();
  VOXELGI_CHECK(gi->GetAllocatedBytes(vtkVoxelGIPass::RESOURCE_SHADOW_MAPS) == 0, "shadow maps allocated");
  VOXELGI_CHECK(gi->GetAllocatedBytes(vtkVoxelGIPass::RESOURCE_DIRECT) > 0, "no direct volume for bounces");
  VOXELGI_CHECK(gi->GetAllocatedBytes(vtkVoxelGIPass::RESOURCE_DIRECTIONAL) > 0, "no anisotropic volumes");
  gi->SetBounces(0);
  gi->AnisotropicMipmapsOff();
  vtkVoxelGIPass::SetPropEmission(cube, 2.0, 2.0, 2.0);
  window->Render();
  VOXELGI_CHECK(gi->GetAllocatedBytes(vtkVoxelGIPass::RESOURCE_DIRECT) == 0, "direct volume without bounces");
  VOXELGI_CHECK(gi->GetAllocatedBytes(vtkVoxelGIPass::RESOURCE_DIRECTIONAL) == 0, "anisotropic volumes while isotropic");
  VOXELGI_CHECK(gi->GetAllocatedBytes(vtkVoxelGIPass::RESOURCE_EMISSION) > 0, "no emission volume for an emitter");
  std::cout << "voxel memory " << gi->GetVoxelMemoryBytes() << " bytes" << std::endl;
  return EXIT_SUCCESS;
}
