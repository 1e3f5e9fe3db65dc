// Stiff and extreme cases: each must render a correct image or say clearly what is wrong,
// never crash, never let a NaN or Inf reach the composited image or the radiance volume,
// and keep VTK's own image when GI cannot run.
//
//   TestStiffCases <case>     one case (CTest runs each as VoxelGI::Stiff.<case>)
//   TestStiffCases            all cases in one process
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellPicker.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataObject.h"
#include "vtkHardwareSelector.h"
#include "vtkSelection.h"
#include "vtkCellArray.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOutputWindow.h"
#include "vtkStringOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkSSAOPass.h"
#include "vtkSequencePass.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkShadowMapPass.h"
#include "vtkRenderPassCollection.h"
#include "vtkCameraPass.h"
#include "vtkRenderStepsPass.h"
#include "vtkUnsignedCharArray.h"
#include "vtkOpenGLState.h"
#include "vtk_glew.h"

#include <dlfcn.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace
{
using glm::dvec3;
using voxelgi_test::Bounded;
using voxelgi_test::Composite;
using voxelgi_test::MaxDifference;

using voxelgi_test::Messages;

// A scene: renderer, window, pass and message capture.
struct Scene : voxelgi_test::GIWindow
{
  Messages Log{ GI };
  Scene()
    : GIWindow(nullptr, 32, 80)
  {
  }
  void Render()
  {
    this->Renderer->ResetCamera();
    this->Window->Render();
  }
};

// Sets an environment variable while it lives, then restores it.
class ScopedEnvironment
{
public:
  ScopedEnvironment(const char* name, const char* value)
    : Name(name)
  {
    if (const char* previous = std::getenv(name))
    {
      this->Previous = previous;
      this->HadPrevious = true;
    }
    setenv(name, value, 1);
  }
  ~ScopedEnvironment()
  {
    if (this->HadPrevious)
    {
      setenv(this->Name.c_str(), this->Previous.c_str(), 1);
    }
    else
    {
      unsetenv(this->Name.c_str());
    }
  }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

private:
  std::string Name;
  std::string Previous;
  bool HadPrevious = false;
};

vtkActor* AddPolyData(vtkRenderer* renderer, vtkPolyData* poly)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  return actor;
}

vtkSmartPointer<vtkPolyData> Triangles(const std::vector<dvec3>& corners)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  for (std::size_t i = 0; i + 2 < corners.size(); i += 3)
  {
    vtkIdType ids[3];
    for (int k = 0; k < 3; ++k)
    {
      ids[k] = points->InsertNextPoint(corners[i + k].x, corners[i + k].y, corners[i + k].z);
    }
    cells->InsertNextCell(3, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(cells);
  return poly;
}

vtkActor* AddBox(vtkRenderer* renderer, double x0, double x1, double y0, double y1, double z0, double z1)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(x0, x1, y0, y1, z0, z1);
  // Double precision points: in float, a unit box 1e8 from the origin collapses to a point.
  cube->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  return vtkVoxelGIScenes::AddSource(renderer, cube, 0.8, 0.7, 0.6);
}

// Occupied voxels (albedo alpha) of the last voxelization.
int Occupied(vtkVoxelGIPass* gi)
{
  vtkNew<vtkImageData> albedo;
  if (!gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, albedo))
  {
    return 0;
  }
  vtkDataArray* a = albedo->GetPointData()->GetScalars();
  int n = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    n += a->GetComponent(i, 3) > 0 ? 1 : 0;
  }
  return n;
}

// A lit unit box scaled by `scale` and moved by `offset`: GI must run and voxelize it as it
// does the unscaled box at the origin.
int ScaledBox(double scale, double offset)
{
  Scene reference;
  AddBox(reference.Renderer, -0.5, 0.5, -0.5, 0.5, -0.5, 0.5);
  reference.Render();
  Scene s;
  AddBox(s.Renderer, offset - 0.5 * scale, offset + 0.5 * scale, offset - 0.5 * scale,
    offset + 0.5 * scale, offset - 0.5 * scale, offset + 0.5 * scale);
  s.Render();
  VOXELGI_CHECK(s.GI->GetGIActive(), "GI did not run: " << s.Log.Text);
  VOXELGI_CHECK(Bounded(s.GI), "non-finite or unbounded values");
  const int expected = Occupied(reference.GI), got = Occupied(s.GI);
  std::cout << "scale " << scale << ", offset " << offset << ": " << got << " voxels (unit box "
            << expected << ")" << std::endl;
  VOXELGI_CHECK(got == expected, "voxelization depends on the scene's scale or position");
  return EXIT_SUCCESS;
}

// Renders `s` once more, fully recomputed, and compares with `before`.
bool Unchanged(Scene& s, vtkFloatArray* before, const char* after)
{
  s.GI->Invalidate();
  s.Window->Render();
  const double d = MaxDifference(before, Composite(s.GI));
  std::cout << "after " << after << ": GI active " << s.GI->GetGIActive()
            << ", largest difference " << d << std::endl;
  return s.GI->GetGIActive() && d == 0.0;
}

const voxelgi_test::Cases& Cases()
{
  static const voxelgi_test::Cases cases = {
    { "EmptyRenderer",
      [] {
        Scene s;
        s.Render();
        VOXELGI_CHECK(!s.GI->GetGIActive(), "GI ran on nothing");
        return EXIT_SUCCESS;
      } },
    { "OnlyLinesAndPoints",
      [] {
        Scene s;
        vtkNew<vtkPoints> points;
        points->InsertNextPoint(0, 0, 0);
        points->InsertNextPoint(1, 0, 0);
        points->InsertNextPoint(1, 1, 0);
        vtkNew<vtkCellArray> lines;
        vtkIdType line[2] = { 0, 1 };
        lines->InsertNextCell(2, line);
        vtkNew<vtkCellArray> verts;
        vtkIdType vert[1] = { 2 };
        verts->InsertNextCell(1, vert);
        vtkNew<vtkPolyData> poly;
        poly->SetPoints(points);
        poly->SetLines(lines);
        poly->SetVerts(verts);
        AddPolyData(s.Renderer, poly);
        vtkActor* wire = AddBox(s.Renderer, 2, 3, 0, 1, 0, 1);
        wire->GetProperty()->SetRepresentationToWireframe();
        s.Render();
        // the line/vertex actor has no area; the wireframe box is left to VTK with a notice
        VOXELGI_CHECK(s.Log.Has("Rendered by VTK without voxel GI"), "no notice: " << s.Log.Text);
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        return EXIT_SUCCESS;
      } },
    { "ZeroPoints",
      [] {
        Scene s;
        vtkNew<vtkPolyData> empty;
        AddPolyData(s.Renderer, empty);
        s.Render();
        VOXELGI_CHECK(!s.GI->GetGIActive(), "GI ran on an empty actor");
        return EXIT_SUCCESS;
      } },
    { "FlatScene",
      [] {
        Scene s;
        voxelgi_test::AddQuad(s.Renderer, dvec3(-1, -1, 0), dvec3(1, -1, 0), dvec3(-1, 1, 0), 0.8, 0.8, 0.8);
        s.Render();
        VOXELGI_CHECK(s.GI->GetGIActive() && Occupied(s.GI) > 0, "flat scene not voxelized");
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        return EXIT_SUCCESS;
      } },
    { "SinglePoint",
      [] {
        Scene s; // one triangle collapsed to a point: zero-volume bounds
        AddPolyData(s.Renderer, Triangles({ dvec3(2, 3, 4), dvec3(2, 3, 4), dvec3(2, 3, 4) }));
        s.Render();
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        VOXELGI_CHECK(Occupied(s.GI) == 0, "a zero-area triangle was voxelized");
        return EXIT_SUCCESS;
      } },
    { "ExtremeAspectRatio",
      [] {
        Scene s;
        AddBox(s.Renderer, 0, 1000, 0, 1, 0, 1);
        s.Render();
        VOXELGI_CHECK(s.GI->GetGIActive() && Occupied(s.GI) > 0, "1000:1:1 box not voxelized");
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        return EXIT_SUCCESS;
      } },
    { "TinyScene", [] { return ScaledBox(1e-6, 0.0); } },
    { "HugeScene", [] { return ScaledBox(1e6, 0.0); } },
    { "OffsetScene", [] { return ScaledBox(1.0, 1e8); } },
    { "FarOffsetScene", [] { return ScaledBox(1.0, 1e9); } },
    { "NaNAndInfCoordinates",
      [] {
        Scene s;
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        AddPolyData(s.Renderer, Triangles({ dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(nan, 1, 0),
                                  dvec3(0, 0, 1), dvec3(inf, 0, 1), dvec3(0, 1, 1) }));
        AddBox(s.Renderer, 0, 1, 0, 1, 0, 1);
        s.Window->Render();
        VOXELGI_CHECK(s.Log.Has("points with NaN or Inf coordinates"), "no message: " << s.Log.Text);
        VOXELGI_CHECK(s.GI->GetGIActive(), "GI did not run for the valid actor");
        // The same inside a block of a composite dataset (ParaView's mappers draw those).
        Scene c;
        vtkNew<vtkMultiBlockDataSet> blocks;
        blocks->SetNumberOfBlocks(2);
        blocks->SetBlock(0, Triangles({ dvec3(2, 0, 0), dvec3(3, 0, 0), dvec3(nan, 1, 0) }));
        blocks->SetBlock(1, Triangles({ dvec3(2, 0, 1), dvec3(3, 0, 1), dvec3(2, 1, 1) }));
        vtkNew<vtkCompositePolyDataMapper2> compositeMapper;
        compositeMapper->SetInputDataObject(blocks);
        vtkNew<vtkActor> compositeActor;
        compositeActor->SetMapper(compositeMapper);
        c.Renderer->AddActor(compositeActor);
        AddBox(c.Renderer, 0, 1, 0, 1, 0, 1);
        c.Window->Render();
        VOXELGI_CHECK(c.Log.Has("1 of 6 points with NaN or Inf coordinates"),
          "no message for the composite block: " << c.Log.Text);
        VOXELGI_CHECK(c.GI->GetGIActive() && Bounded(c.GI), "GI did not run, or non-finite values");
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        return EXIT_SUCCESS;
      } },
    { "BadNormals",
      [] {
        Scene s; // NaN, zero-length and flipped normals on a sphere
        vtkNew<vtkSphereSource> sphere;
        sphere->Update();
        vtkNew<vtkPolyData> poly;
        poly->DeepCopy(sphere->GetOutput());
        vtkDataArray* normals = poly->GetPointData()->GetNormals();
        for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
        {
          const double* n = normals->GetTuple3(i);
          const double bad[3][3] = { { std::nan(""), 0, 0 }, { 0, 0, 0 }, { -n[0], -n[1], -n[2] } };
          normals->SetTuple(i, bad[i % 3]);
        }
        AddPolyData(s.Renderer, poly);
        vtkNew<vtkPolyData> noNormals;
        noNormals->DeepCopy(sphere->GetOutput());
        noNormals->GetPointData()->SetNormals(nullptr);
        AddPolyData(s.Renderer, noNormals)->SetPosition(1.5, 0, 0);
        s.Render();
        VOXELGI_CHECK(s.GI->GetGIActive() && Occupied(s.GI) > 0, "not voxelized");
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        return EXIT_SUCCESS;
      } },
    { "DegenerateSliverDuplicate",
      [] {
        Scene s;
        AddPolyData(s.Renderer, Triangles({ dvec3(0, 0, 0), dvec3(1, 1, 1), dvec3(2, 2, 2), // collinear
                                  dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(0.5, 1e-9, 0),        // sliver
                                  dvec3(0, 0, 1), dvec3(1, 0, 1), dvec3(0, 1, 1),
                                  dvec3(0, 0, 1), dvec3(1, 0, 1), dvec3(0, 1, 1) }));         // duplicate
        s.Render();
        VOXELGI_CHECK(s.GI->GetGIActive() && Occupied(s.GI) > 0, "not voxelized");
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        return EXIT_SUCCESS;
      } },
    { "MillionTrianglesOneVoxel",
      [] {
        Scene s; // 1M tiny triangles in one voxel (plus two anchors): the count must not wrap
        const int n = 1000000;
        std::vector<dvec3> corners{ dvec3(0, 0, 0), dvec3(0.01, 0, 0), dvec3(0, 0.01, 0),
          dvec3(1, 1, 1), dvec3(0.99, 1, 1), dvec3(1, 0.99, 1) };
        corners.reserve(3 * (n + 2));
        for (int i = 0; i < n; ++i)
        {
          const double z = 0.505 + 0.01 * (i % 100) / 100.0;
          corners.insert(corners.end(), { dvec3(0.505, 0.505, z), dvec3(0.515, 0.505, z), dvec3(0.505, 0.515, z) });
        }
        AddPolyData(s.Renderer, Triangles(corners));
        s.GI->SetVoxelResolution(16);
        s.Render();
        vtkNew<vtkImageData> counts;
        VOXELGI_CHECK(s.GI->GetVoxelVolume(vtkVoxelGIPass::VOLUME_COUNT, counts), "no counts");
        double maximum = 0;
        vtkDataArray* c = counts->GetPointData()->GetScalars();
        for (vtkIdType i = 0; i < c->GetNumberOfTuples(); ++i)
        {
          maximum = std::max(maximum, c->GetTuple1(i));
        }
        std::cout << "fragments in the fullest voxel: " << maximum << std::endl;
        VOXELGI_CHECK(maximum == n, "fragment count " << maximum);
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        return EXIT_SUCCESS;
      } },
    { "ExtremeIntensities",
      [] {
        Scene s;
        vtkVoxelGIScenes::AddCornellBox(s.Renderer, 1e6); // emission 1e6
        vtkLight* light = vtkLight::SafeDownCast(s.Renderer->GetLights()->GetItemAsObject(0));
        light->SetIntensity(1e6);
        s.Window->Render();
        VOXELGI_CHECK(s.GI->GetGIActive(), "GI did not run");
        VOXELGI_CHECK(Bounded(s.GI), "intensity 1e6 produced non-finite or unbounded values");
        light->SetIntensity(0.0);
        s.Window->Render();
        VOXELGI_CHECK(Bounded(s.GI), "intensity 0 produced non-finite values");
        return EXIT_SUCCESS;
      } },
    { "NegativeValues",
      [] {
        Scene s;
        vtkActor* box = AddBox(s.Renderer, 0, 1, 0, 1, 0, 1);
        vtkVoxelGIPass::SetPropEmission(box, -1.0, 0.0, 0.0);
        vtkNew<vtkLight> light;
        light->SetIntensity(-2.0);
        s.Renderer->AddLight(light);
        vtkNew<vtkLight> good;
        s.Renderer->AddLight(good);
        // NaN position, negative attenuation, NaN spot exponent: left out, each named.
        const double nan = std::numeric_limits<double>::quiet_NaN();
        vtkNew<vtkLight> lost;
        lost->SetPosition(nan, 1.0, 1.0);
        s.Renderer->AddLight(lost);
        vtkNew<vtkLight> fading;
        fading->SetPositional(true);
        fading->SetAttenuationValues(1.0, -0.5, 0.0);
        s.Renderer->AddLight(fading);
        vtkNew<vtkLight> spot;
        spot->SetPositional(true);
        spot->SetConeAngle(30.0);
        spot->SetExponent(nan);
        s.Renderer->AddLight(spot);
        vtkNew<vtkLight> unattenuated; // its radiance saturated the half floats before
        unattenuated->SetPositional(true);
        unattenuated->SetAttenuationValues(0.0, 0.0, 0.0);
        s.Renderer->AddLight(unattenuated);
        Messages global{ vtkOutputWindow::GetInstance() };
        s.Render();
        VOXELGI_CHECK(s.Log.Has("5 light(s) with"), "no message: " << s.Log.Text);
        VOXELGI_CHECK(s.Log.Has("attenuation (0, 0, 0)"), "no message: " << s.Log.Text);
        VOXELGI_CHECK(s.Log.Has("negative or non-finite intensity"), "no message: " << s.Log.Text);
        VOXELGI_CHECK(s.Log.Has("non-finite position or focal point"), "no message: " << s.Log.Text);
        VOXELGI_CHECK(s.Log.Has("negative or non-finite attenuation"), "no message: " << s.Log.Text);
        VOXELGI_CHECK(s.Log.Has("non-finite spot exponent"), "no message: " << s.Log.Text);
        VOXELGI_CHECK(s.GI->GetGIActive(), "the valid light did not light the scene");
        VOXELGI_CHECK(s.GI->GetAllocatedBytes(vtkVoxelGIPass::RESOURCE_EMISSION) == 0,
          "negative emission was accepted");
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        // one light of intensity 1 on a box of albedo 0.8: no pixel near the half-float limit
        vtkSmartPointer<vtkFloatArray> image = Composite(s.GI);
        VOXELGI_CHECK(image && image->GetValueRange()[1] < 4.0,
          "composite reaches " << (image ? image->GetValueRange()[1] : -1.0));
        return EXIT_SUCCESS;
      } },
    { "LightInsideGeometry",
      [] {
        Scene s;
        AddBox(s.Renderer, -1, 1, -1, 1, -1, 1);
        vtkNew<vtkLight> light;
        light->SetLightTypeToSceneLight();
        light->SetPositional(true);
        light->SetPosition(0, 0, 0);
        s.Renderer->AddLight(light);
        s.Render();
        VOXELGI_CHECK(s.GI->GetGIActive(), "GI did not run");
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        return EXIT_SUCCESS;
      } },
    { "SpotConeLimits",
      [] {
        Scene s;
        voxelgi_test::AddQuad(s.Renderer, dvec3(-2, 0, -2), dvec3(-2, 0, 2), dvec3(2, 0, -2), 0.8, 0.8, 0.8);
        vtkNew<vtkLight> spot;
        spot->SetLightTypeToSceneLight();
        spot->SetPositional(true);
        spot->SetPosition(0, 2, 0);
        spot->SetFocalPoint(0, 0, 0);
        s.Renderer->AddLight(spot);
        for (double cone : { 0.0, 90.0 })
        {
          spot->SetConeAngle(cone);
          s.Render();
          VOXELGI_CHECK(s.GI->GetGIActive(), "GI did not run for cone " << cone);
          VOXELGI_CHECK(Bounded(s.GI), "non-finite values for cone " << cone);
        }
        return EXIT_SUCCESS;
      } },
    { "SettingsBeyondBounds",
      [] {
        Scene s;
        vtkVoxelGIScenes::AddCornellBox(s.Renderer);
        s.GI->SetVoxelResolution(4096);
        VOXELGI_CHECK(s.GI->GetVoxelResolution() == 512 && s.Log.Has("MiB of voxel memory"),
          "4096 not clamped with the memory it needs: " << s.Log.Text);
        s.GI->SetVoxelResolution(1);
        VOXELGI_CHECK(s.GI->GetVoxelResolution() == 16, "1 not clamped");
        s.GI->SetDiffuseConeAperture(0.0);
        s.GI->SetShadowConeAperture(180.0);
        s.GI->SetConeStepFactor(0.0); // clamped: no endless loop
        s.GI->SetMaxTraceDistance(0.0);
        s.GI->SetBounces(10);
        s.Window->Render();
        VOXELGI_CHECK(s.GI->GetGIActive(), "GI did not run");
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        s.GI->SetDiffuseConeAperture(180.0);
        s.GI->SetMaxTraceDistance(2.0);
        s.Window->Render();
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values with the widest cones");
        return EXIT_SUCCESS;
      } },
    { "OldOpenGLContext",
      [] {
        // Both windows get a real OpenGL 3.3 core context (VTK needs 3.2, GI 4.3): Mesa reads
        // these at each context creation, so the cases after this one get the driver's version.
        ScopedEnvironment glVersion("MESA_GL_VERSION_OVERRIDE", "3.3");
        ScopedEnvironment glslVersion("MESA_GLSL_VERSION_OVERRIDE", "330");
        Scene s;
        vtkVoxelGIScenes::AddCornellBox(s.Renderer);
        s.Window->Render();
        int major = 0;
        int minor = 0;
        vtkOpenGLRenderWindow::SafeDownCast(s.Window)->GetOpenGLVersion(major, minor);
        VOXELGI_CHECK(major == 3 && minor == 3,
          "the driver made an OpenGL " << major << "." << minor
                                       << " context, not 3.3 (MESA_GL_VERSION_OVERRIDE ignored)");
        VOXELGI_CHECK(!s.GI->GetGIActive(), "GI ran on a 3.3 context");
        VOXELGI_CHECK(s.Log.Has("needs OpenGL 4.3") && s.Log.Has("provides 3.3") &&
            s.Log.Has("without GI"),
          "no clear error: " << s.Log.Text);
        // VTK's own image is still shown: it matches a renderer without the pass
        vtkNew<vtkUnsignedCharArray> withPass;
        s.Window->GetRGBACharPixelData(0, 0, 79, 79, 0, withPass);
        Scene plain;
        vtkVoxelGIScenes::AddCornellBox(plain.Renderer);
        plain.Renderer->SetPass(nullptr);
        plain.Window->Render();
        vtkNew<vtkUnsignedCharArray> without;
        plain.Window->GetRGBACharPixelData(0, 0, 79, 79, 0, without);
        for (vtkIdType i = 0; i < without->GetNumberOfValues(); ++i)
        {
          VOXELGI_CHECK(withPass->GetValue(i) == without->GetValue(i), "VTK's image not kept");
        }
        return EXIT_SUCCESS;
      } },
    { "OutOfMemory",
      [] {
        // 256^3 voxels of an emissive scene under an address-space limit that leaves 256 MiB:
        // refused before allocating, said once, nothing left allocated, VTK's image; GI
        // again once the resolution fits.
        Scene s;
        vtkVoxelGIScenes::AddCornellBox(s.Renderer);
        s.Window->Render();
        VOXELGI_CHECK(s.GI->GetGIActive(), "GI did not run at 32^3: " << s.Log.Text);
        const unsigned long long held = s.GI->GetVoxelMemoryBytes();
        std::cout << "32^3 holds " << held << " bytes, predicted "
                  << s.GI->GetRequiredVoxelMemoryBytes(true) << std::endl;
        VOXELGI_CHECK(held == s.GI->GetRequiredVoxelMemoryBytes(true), "prediction differs");
        struct rlimit before;
        getrlimit(RLIMIT_AS, &before);
        long long pages = 0;
        std::ifstream("/proc/self/statm") >> pages;
        struct rlimit limited = before;
        limited.rlim_cur = static_cast<rlim_t>(pages * sysconf(_SC_PAGESIZE)) + (256u << 20);
        setrlimit(RLIMIT_AS, &limited);
        s.GI->SetVoxelResolution(256);
        for (int frame = 0; frame < 3; ++frame)
        {
          s.Window->Render();
        }
        // Invalidate() retries the refused settings: checked again, and refused again once.
        const std::string once = s.Log.Text;
        s.GI->Invalidate();
        s.Window->Render();
        s.Window->Render();
        setrlimit(RLIMIT_AS, &before);
        const std::size_t first = once.find("VoxelResolution 256 needs");
        const std::size_t again = s.Log.Text.find("VoxelResolution 256 needs", once.size());
        VOXELGI_CHECK(again != std::string::npos, "Invalidate() did not retry: " << s.Log.Text);
        VOXELGI_CHECK(s.Log.Text.find("Voxel GI disabled", again + 1) == std::string::npos,
          "the retry's error was repeated");
        s.Log.Text = once;
        VOXELGI_CHECK(first != std::string::npos && s.Log.Has("MiB are free (address space") &&
            s.Log.Has("until a setting changes"),
          "no clear error: " << s.Log.Text);
        VOXELGI_CHECK(s.Log.Text.find("Voxel GI disabled", first + 1) == std::string::npos,
          "the error was repeated");
        VOXELGI_CHECK(!s.GI->GetGIActive(), "GI reported active");
        VOXELGI_CHECK(s.GI->GetVoxelMemoryBytes() == 0, "memory left allocated while GI is off");
        vtkNew<vtkUnsignedCharArray> refused;
        s.Window->GetRGBACharPixelData(0, 0, 79, 79, 0, refused);
        Scene plain;
        vtkVoxelGIScenes::AddCornellBox(plain.Renderer);
        plain.GI->EnabledOff();
        plain.Window->Render();
        vtkNew<vtkUnsignedCharArray> without;
        plain.Window->GetRGBACharPixelData(0, 0, 79, 79, 0, without);
        VOXELGI_CHECK(MaxDifference(refused, without) == 0.0, "not VTK's image");
        s.GI->SetVoxelResolution(32);
        s.Window->Render();
        VOXELGI_CHECK(s.GI->GetGIActive() && Bounded(s.GI), "GI did not come back");
        return EXIT_SUCCESS;
      } },
    { "EmittersOfVeryDifferentRadiance",
      [] {
        // Radiance 1000 and 0.5 side by side. Quantized relative to the brightest emitter in
        // 8 bits (before), the dim one emitted nothing; each voxel now keeps its radiance.
        Scene s;
        vtkActor* bright = voxelgi_test::AddQuad(
          s.Renderer, dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(0, 0, 1), 1.0, 1.0, 1.0);
        vtkActor* dim = voxelgi_test::AddQuad(
          s.Renderer, dvec3(3, 0, 0), dvec3(4, 0, 0), dvec3(3, 0, 1), 1.0, 1.0, 1.0);
        vtkVoxelGIPass::SetPropEmission(bright, 1000.0, 1000.0, 1000.0);
        vtkVoxelGIPass::SetPropEmission(dim, 0.5, 0.25, 0.125);
        s.Render();
        VOXELGI_CHECK(s.GI->GetGIActive(), "GI did not run: " << s.Log.Text);
        vtkNew<vtkImageData> emission;
        VOXELGI_CHECK(
          s.GI->GetVoxelVolume(vtkVoxelGIPass::VOLUME_EMISSION, emission), "no emission volume");
        double origin[3];
        s.GI->GetGridOrigin(origin);
        const double size = s.GI->GetGridVoxelSize();
        const int n = s.GI->GetGridResolution();
        vtkDataArray* e = emission->GetPointData()->GetScalars();
        double brightest[3] = { 0, 0, 0 }, dimmest[3] = { 0, 0, 0 };
        for (vtkIdType i = 0; i < e->GetNumberOfTuples(); ++i)
        {
          const double x = origin[0] + (static_cast<double>(i % n) + 0.5) * size;
          double* side = x < 2.0 ? brightest : dimmest;
          for (int c = 0; c < 3; ++c)
          {
            side[c] = std::max(side[c], e->GetComponent(i, c));
          }
        }
        std::cout << "largest voxel emission: bright (" << brightest[0] << ", " << brightest[1]
                  << ", " << brightest[2] << "), dim (" << dimmest[0] << ", " << dimmest[1]
                  << ", " << dimmest[2] << ")" << std::endl;
        VOXELGI_CHECK(brightest[0] == 1000.0 && brightest[2] == 1000.0, "bright emitter changed");
        VOXELGI_CHECK(dimmest[0] == 0.5 && dimmest[1] == 0.25 && dimmest[2] == 0.125,
          "dim emitter's radiance not kept");
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        return EXIT_SUCCESS;
      } },
    { "ScreenSpaceAOCombined",
      [] {
        // vtkSSAOPass as the pass's delegate, and the pass as vtkSSAOPass's delegate: both
        // are refused once and draw exactly what vtkSSAOPass around VTK's steps draws.
        enum Arrangement { SSAO_ONLY, SSAO_IN_GI, GI_IN_SSAO };
        auto render = [](Arrangement arrangement, vtkUnsignedCharArray* pixels) {
          Scene s;
          vtkVoxelGIScenes::AddCornellBox(s.Renderer);
          Messages global{ vtkOutputWindow::GetInstance() };
          vtkNew<vtkSSAOPass> ssao;
          vtkNew<vtkRenderStepsPass> steps;
          ssao->SetRadius(0.1);
          ssao->SetDelegatePass(arrangement == GI_IN_SSAO ? static_cast<vtkRenderPass*>(s.GI)
                                                          : steps.GetPointer());
          if (arrangement == SSAO_IN_GI)
          {
            s.GI->SetDelegatePass(ssao);
          }
          s.Renderer->SetPass(arrangement == SSAO_IN_GI ? static_cast<vtkRenderPass*>(s.GI)
                                                        : ssao.GetPointer());
          s.Window->Render();
          s.Window->Render();
          s.Window->GetRGBACharPixelData(0, 0, 79, 79, 0, pixels);
          const std::size_t first = s.Log.Text.find("Voxel GI cannot run here");
          std::cout << "arrangement " << arrangement << ": " << s.Log.Text << global.Text
                    << std::endl;
          return global.Text.empty() && !s.GI->GetGIActive() &&
            (arrangement == SSAO_ONLY
                ? s.Log.Text.empty()
                : first != std::string::npos &&
                  s.Log.Text.find("Voxel GI cannot run here", first + 1) == std::string::npos &&
                  s.Log.Has(arrangement == SSAO_IN_GI ? "its delegate is a vtkSSAOPass"
                                                      : "the delegate of a vtkSSAOPass"));
        };
        vtkNew<vtkUnsignedCharArray> reference;
        VOXELGI_CHECK(render(SSAO_ONLY, reference), "vtkSSAOPass alone");
        for (Arrangement arrangement : { SSAO_IN_GI, GI_IN_SSAO })
        {
          vtkNew<vtkUnsignedCharArray> pixels;
          VOXELGI_CHECK(render(arrangement, pixels), "not refused once, or other messages");
          VOXELGI_CHECK(MaxDifference(reference, pixels) == 0.0,
            "arrangement " << arrangement << " differs from vtkSSAOPass alone");
        }
        return EXIT_SUCCESS;
      } },
    { "ShadowMapPassCombined",
      [] {
        // A program's shadows as vedo sets them (a camera pass around a sequence of
        // vtkShadowMapPass's baker and the pass) as GI's delegate: GI runs, and says once
        // that both draw the lights' shadows while ConeShadows is on; off, nothing is said.
        Scene s;
        vtkVoxelGIScenes::AddCornellBox(s.Renderer);
        vtkNew<vtkShadowMapPass> shadows;
        vtkNew<vtkRenderPassCollection> steps;
        steps->AddItem(shadows->GetShadowMapBakerPass());
        steps->AddItem(shadows);
        vtkNew<vtkSequencePass> sequence;
        sequence->SetPasses(steps);
        vtkNew<vtkCameraPass> camera;
        camera->SetDelegatePass(sequence);
        s.GI->SetDelegatePass(camera);
        s.Window->Render();
        s.Window->Render();
        std::cout << s.Log.Text << std::endl;
        VOXELGI_CHECK(s.GI->GetGIActive(), "GI did not run");
        const std::size_t first = s.Log.Text.find("A vtkShadowMapPass is among");
        VOXELGI_CHECK(first != std::string::npos && s.Log.Has("Set ConeShadows off"),
          "not said: " << s.Log.Text);
        VOXELGI_CHECK(s.Log.Text.find("A vtkShadowMapPass", first + 1) == std::string::npos,
          "said twice");
        s.GI->SetConeShadows(false);
        s.Log.Text.clear();
        s.Window->Render();
        VOXELGI_CHECK(
          s.GI->GetGIActive() && s.Log.Text.empty(), "with ConeShadows off: " << s.Log.Text);
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        return EXIT_SUCCESS;
      } },
    { "SoftwareRenderer",
      [] {
        // The software profile chosen by Auto where the context's renderer runs on the CPU
        // (CI's llvmpipe), said once: a 128^3 setting voxelizes at 64^3. On a GPU nothing
        // is said and 128^3 stays. On, the profile caps on any renderer.
        Scene s;
        vtkVoxelGIScenes::AddCornellBox(s.Renderer);
        s.GI->SetSoftwareProfileToAuto();
        s.GI->SetVoxelResolution(128);
        s.Window->Render();
        const std::string capabilities = s.Window->ReportCapabilities();
        const bool cpu = capabilities.find("llvmpipe") != std::string::npos ||
          capabilities.find("softpipe") != std::string::npos;
        s.Window->Render();
        auto dimension = [&] {
          vtkNew<vtkImageData> albedo;
          return s.GI->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, albedo)
            ? albedo->GetDimensions()[0]
            : 0;
        };
        const std::size_t first = s.Log.Text.find("OpenGL runs on the CPU here");
        std::cout << (cpu ? "CPU renderer: " : "GPU renderer: ") << s.Log.Text << std::endl;
        VOXELGI_CHECK(s.GI->GetGIActive(), "GI did not run");
        VOXELGI_CHECK(dimension() == (cpu ? 64 : 128), "grid of " << dimension());
        VOXELGI_CHECK(cpu ? first != std::string::npos &&
              s.Log.Text.find("OpenGL runs on the CPU", first + 1) == std::string::npos
                          : s.Log.Text.empty(),
          "said: " << s.Log.Text);
        s.GI->SetSoftwareProfileToOn();
        s.GI->SetVoxelResolution(96);
        s.Window->Render();
        VOXELGI_CHECK(dimension() == 64, "On: grid of " << dimension());
        // Off: no warning, but on a CPU renderer the slow first frame at 128^3 is said once,
        // as text.
        s.GI->SetSoftwareProfileToOff();
        s.GI->SetVoxelResolution(128);
        s.Log.Text.clear();
        vtkNew<vtkStringOutputWindow> output;
        vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
        vtkOutputWindow::SetInstance(output);
        s.Window->Render();
        s.GI->Invalidate();
        s.Window->Render();
        vtkOutputWindow::SetInstance(previous);
        VOXELGI_CHECK(dimension() == 128 && s.Log.Text.empty(), "Off: grid of " << dimension());
        const std::string said = output->GetOutput();
        const std::size_t slow = said.find("with SoftwareProfile Off");
        VOXELGI_CHECK(cpu ? slow != std::string::npos &&
              said.find("with SoftwareProfile Off", slow + 1) == std::string::npos
                          : slow == std::string::npos,
          "Off, said: " << said);
        return EXIT_SUCCESS;
      } },
    { "ResizeEveryFrameAndRelease",
      [] {
        Scene s;
        vtkVoxelGIScenes::AddCornellBox(s.Renderer);
        for (int frame = 0; frame < 6; ++frame)
        {
          s.Window->SetSize(60 + 17 * frame, 90 - 9 * frame);
          s.Window->Render();
          VOXELGI_CHECK(s.GI->GetGIActive() && Bounded(s.GI), "frame " << frame);
          if (frame == 2)
          {
            s.GI->ReleaseGraphicsResources(s.Window);
          }
          if (frame == 3)
          {
            s.Renderer->SetPass(nullptr); // removed ...
            s.Window->Render();
            s.Renderer->SetPass(s.GI); // ... and added again
          }
        }
        return EXIT_SUCCESS;
      } },
    { "LayersAndWindows",
      [] {
        Scene s; // two renderers in two layers of one window, each with its own pass
        vtkVoxelGIScenes::AddCornellBox(s.Renderer);
        s.Renderer->SetViewport(0.0, 0.0, 0.6, 1.0);
        vtkNew<vtkRenderer> overlay;
        overlay->SetLayer(1);
        overlay->SetViewport(0.5, 0.0, 1.0, 1.0);
        AddBox(overlay, 0, 1, 0, 1, 0, 1);
        s.Window->SetNumberOfLayers(2);
        s.Window->AddRenderer(overlay);
        vtkNew<vtkVoxelGIPass> second;
        second->SetSoftwareProfileToOff();
        second->SetVoxelResolution(16);
        overlay->SetPass(second);
        Scene other; // and a second window
        vtkVoxelGIScenes::AddCornellBox(other.Renderer);
        for (int frame = 0; frame < 2; ++frame)
        {
          s.Window->Render();
          other.Window->Render();
        }
        VOXELGI_CHECK(s.GI->GetGIActive() && second->GetGIActive() && other.GI->GetGIActive(),
          "a pass did not run");
        VOXELGI_CHECK(Bounded(s.GI) && Bounded(second) && Bounded(other.GI), "non-finite values");
        return EXIT_SUCCESS;
      } },
    { "CleanupOfOneWindowKeepsAnother",
      [] {
        // GL objects must be freed on their own context, never on whichever is current.
        Scene a, b;
        vtkVoxelGIScenes::AddCornellBox(a.Renderer);
        vtkVoxelGIScenes::AddCornellBox(b.Renderer);
        a.Render();
        b.Render();
        vtkSmartPointer<vtkFloatArray> before = Composite(b.GI);
        b.Window->MakeCurrent();
        a.Window->RemoveRenderer(a.Renderer);
        VOXELGI_CHECK(Unchanged(b, before, "removing A's renderer"), "window B lost its GI");
        vtkNew<vtkRenderer> renderer;
        vtkVoxelGIScenes::AddCornellBox(renderer);
        a.Window->AddRenderer(renderer);
        auto pass = vtkSmartPointer<vtkVoxelGIPass>::New();
        pass->SetSoftwareProfileToOff();
        renderer->SetPass(pass);
        renderer->ResetCamera();
        a.Window->Render();
        VOXELGI_CHECK(pass->GetGIActive(), "the third pass did not run");
        b.Window->MakeCurrent();
        renderer->SetPass(nullptr);
        pass = nullptr; // destroyed while window B is current
        VOXELGI_CHECK(Unchanged(b, before, "destroying a pass of window A"),
          "window B lost its GI");
        return EXIT_SUCCESS;
      } },
    { "OnePassTwoViewports",
      [] {
        // One pass on two viewports of one window: GI for the first, VTK's image and one
        // message for the second, and no rebuild of the first's voxels every frame.
        Scene s;
        vtkVoxelGIScenes::AddCornellBox(s.Renderer);
        s.Renderer->SetViewport(0.0, 0.0, 0.5, 1.0);
        vtkNew<vtkRenderer> right;
        vtkVoxelGIScenes::AddCornellBox(right);
        right->SetViewport(0.5, 0.0, 1.0, 1.0);
        right->SetPass(s.GI);
        s.Window->AddRenderer(right);
        std::string stages;
        for (int frame = 0; frame < 3; ++frame)
        {
          s.Window->Render();
          stages = "";
          for (int stage = 0; stage < vtkVoxelGIPass::NUMBER_OF_STAGES; ++stage)
          {
            stages += s.GI->GetStageRan(stage) ? vtkVoxelGIPass::GetStageName(stage) + std::string(",") : "";
          }
          std::cout << "frame " << frame << ": " << stages << std::endl;
        }
        VOXELGI_CHECK(s.Log.Has("set on two renderers of one window"), "no message: " << s.Log.Text);
        VOXELGI_CHECK(s.GI->GetGIActive() && stages == "Scan,Present,",
          "the first renderer's frame ran " << stages);
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        // Picking by ray casting works with the pass set; hardware picking (VTK 9.1 renders
        // selections only for renderers without a pass) with the pass removed for the pick.
        vtkNew<vtkCellPicker> picker;
        const int* size = s.Window->GetSize();
        const int hit = picker->Pick(0.25 * size[0], 0.5 * size[1], 0.0, s.Renderer);
        VOXELGI_CHECK(hit && picker->GetActor(), "vtkCellPicker found nothing");
        vtkNew<vtkHardwareSelector> selector;
        selector->SetRenderer(s.Renderer);
        selector->SetArea(0, 0, static_cast<unsigned int>(size[0] / 2 - 1),
          static_cast<unsigned int>(size[1] - 1));
        selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
        s.Renderer->SetPass(nullptr);
        vtkSmartPointer<vtkSelection> selection;
        selection.TakeReference(selector->Select());
        s.Renderer->SetPass(s.GI);
        s.Window->Render();
        VOXELGI_CHECK(selection && selection->GetNumberOfNodes() > 0, "hardware selection found nothing");
        VOXELGI_CHECK(s.GI->GetGIActive(), "GI did not resume after the pick");
        return EXIT_SUCCESS;
      } },
    { "VoxelSourceRefused",
      [] {
        // Sharing voxels: not with itself, not through a chain, not across windows (one
        // message, VTK's image), and silently VTK's image while the source has no GI.
        Scene s;
        vtkVoxelGIScenes::AddCornellBox(s.Renderer);
        s.GI->SetVoxelSource(s.GI);
        VOXELGI_CHECK(s.Log.Has("cannot share its own voxels") && !s.GI->GetVoxelSource(),
          "self accepted: " << s.Log.Text);
        vtkNew<vtkVoxelGIPass> middle, last;
        middle->SetSoftwareProfileToOff();
        last->SetSoftwareProfileToOff();
        Messages lastLog(last);
        middle->SetVoxelSource(s.GI);
        last->SetVoxelSource(middle);
        VOXELGI_CHECK(lastLog.Has("shares another pass's voxels itself") && !last->GetVoxelSource(),
          "chain accepted: " << lastLog.Text);
        // A follower in a window of its own.
        vtkNew<vtkRenderer> other;
        vtkVoxelGIScenes::AddCornellBox(other);
        vtkNew<vtkRenderWindow> otherWindow;
        otherWindow->SetSize(80, 80);
        otherWindow->AddRenderer(other);
        other->SetPass(middle);
        Messages middleLog(middle);
        s.Render();
        otherWindow->Render();
        otherWindow->Render();
        VOXELGI_CHECK(s.GI->GetGIActive() && !middle->GetGIActive(), "the other window traced");
        const std::string error = "renders into another window";
        const std::size_t first = middleLog.Text.find(error);
        VOXELGI_CHECK(first != std::string::npos && middleLog.Text.find(error, first + 1) == std::string::npos,
          "not said once: " << middleLog.Text);
        // In one window, behind a source without GI.
        other->SetPass(nullptr);
        vtkNew<vtkRenderer> second;
        vtkVoxelGIScenes::AddCornellBox(second);
        second->SetViewport(0.5, 0.0, 1.0, 1.0);
        s.Renderer->SetViewport(0.0, 0.0, 0.5, 1.0);
        second->SetPass(middle);
        s.Window->AddRenderer(second);
        s.GI->SetEnabled(false);
        s.Window->Render();
        VOXELGI_CHECK(!middle->GetGIActive() && middle->GetNumberOfRenderedProps() > 0,
          "no VTK image behind a source without GI");
        s.GI->SetEnabled(true);
        s.Window->Render();
        VOXELGI_CHECK(middle->GetGIActive() && middle->GetVoxelMemoryBytes() == 0 &&
            middle->GetGridResolution() == s.GI->GetGridResolution(),
          "the follower did not trace the source's grid");
        VOXELGI_CHECK(Bounded(middle), "non-finite values");
        return EXIT_SUCCESS;
      } },
    { "ActorsReleasedThenRevoxelized",
      [] {
        // Releasing the actors' GL resources (VTK does so when props leave a window) must not
        // change what the next voxelization writes: the albedo equals a fresh pass's.
        Scene s;
        vtkVoxelGIScenes::AddCornellBox(s.Renderer);
        s.Render();
        s.Window->Render();
        vtkActorCollection* actors = s.Renderer->GetActors();
        actors->InitTraversal();
        while (vtkActor* actor = actors->GetNextActor())
        {
          actor->ReleaseGraphicsResources(s.Window);
        }
        s.GI->Invalidate();
        s.Window->Render();
        vtkNew<vtkImageData> after;
        VOXELGI_CHECK(s.GI->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, after), "no albedo");
        vtkNew<vtkVoxelGIPass> fresh;
        fresh->SetSoftwareProfileToOff();
        fresh->SetVoxelResolution(32);
        s.Renderer->SetPass(fresh);
        s.Window->Render();
        vtkNew<vtkImageData> expected;
        VOXELGI_CHECK(fresh->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, expected), "no albedo");
        vtkDataArray* a = after->GetPointData()->GetScalars();
        vtkDataArray* b = expected->GetPointData()->GetScalars();
        VOXELGI_CHECK(a->GetNumberOfTuples() == b->GetNumberOfTuples(), "grids differ");
        vtkIdType differing = 0;
        for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
        {
          for (int c = 0; c < 4; ++c)
          {
            if (a->GetComponent(i, c) != b->GetComponent(i, c))
            {
              ++differing;
              break;
            }
          }
        }
        std::cout << differing << " voxels differ from a fresh pass" << std::endl;
        VOXELGI_CHECK(differing == 0, differing << " voxels differ after the release");
        s.Renderer->SetPass(s.GI);
        fresh->ReleaseGraphicsResources(s.Window);
        return EXIT_SUCCESS;
      } },
    { "OnePassTwoWindows",
      [] {
        // One pass on two windows: each frame must equal what a pass of its own renders.
        Scene one, two;
        vtkVoxelGIScenes::AddCornellBox(one.Renderer);
        vtkVoxelGIScenes::AddCornellBox(two.Renderer);
        two.Window->SetSize(64, 96);
        one.Render();
        two.Render();
        vtkSmartPointer<vtkFloatArray> expected[2] = { Composite(one.GI), Composite(two.GI) };
        vtkNew<vtkVoxelGIPass> shared;
        shared->SetSoftwareProfileToOff();
        shared->SetVoxelResolution(32);
        one.Renderer->SetPass(shared);
        two.Renderer->SetPass(shared);
        for (int frame = 0; frame < 4; ++frame)
        {
          Scene& s = frame % 2 == 0 ? one : two;
          s.Window->Render();
          const double d = MaxDifference(expected[frame % 2], Composite(shared));
          std::cout << "frame " << frame << ": largest difference " << d << std::endl;
          VOXELGI_CHECK(shared->GetGIActive() && d == 0.0, "a frame of the shared pass differs");
        }
        return EXIT_SUCCESS;
      } },
    { "NoDelegatePass",
      [] {
        Scene s;
        vtkVoxelGIScenes::AddCornellBox(s.Renderer);
        s.GI->SetDelegatePass(nullptr);
        s.Render();
        s.Render();
        VOXELGI_CHECK(!s.GI->GetGIActive(), "GI reported active without a delegate");
        VOXELGI_CHECK(s.Log.Has("No delegate pass"), "no message: " << s.Log.Text);
        VOXELGI_CHECK(s.Log.Text.find("No delegate pass") == s.Log.Text.rfind("No delegate pass"),
          "the message repeats every frame");
        return EXIT_SUCCESS;
      } },
    { "TextureSizeLimit",
      [] {
        // Issue 19, crash 1: a viewport beyond GL_MAX_TEXTURE_SIZE (either axis), a read-back
        // after every frame (a heap overflow before). GI must refuse such frames with one
        // clear message per size, add no GL error to VTK's own, return no image; back at a
        // normal size it must work again.
        Scene s;
        vtkVoxelGIScenes::AddCornellBox(s.Renderer);
        s.Render();
        auto* gl = vtkOpenGLRenderWindow::SafeDownCast(s.Window);
        gl->MakeCurrent();
        GLint max = 0;
        gl->GetState()->vtkglGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
        // The test does not link libOpenGL itself: take VTK's glGetError.
        using GetError = GLenum (*)();
        auto getError = reinterpret_cast<GetError>(dlsym(RTLD_DEFAULT, "glGetError"));
        VOXELGI_CHECK(getError && max > 0, "no glGetError or GL_MAX_TEXTURE_SIZE");
        while (getError() != GL_NO_ERROR)
        {
        }
        std::cout << "GL_MAX_TEXTURE_SIZE " << max << std::endl;
        struct Step
        {
          int Width, Height;
        };
        const int wide = max + max / 4; // 20480 where the limit is 16384
        const Step steps[] = { { max, 4 }, { max + 1, 4 }, { max + 1, 4 }, { wide, 3 },
          { 4, max + 1 }, { 80, 80 }, { max + 1, 4 }, { 80, 80 } };
        // GL errors of a frame, before and after its renderer starts (GL keeps one flag per
        // error code, so they are drained in between). VTK 9.1's window leaves 0x501 before
        // the renderers when it resizes its own framebuffer beyond the limits, with or without
        // the pass; once the renderer (and so the pass) runs, no error may be added.
        struct Errors
        {
          GetError Get = nullptr;
          int Before = 0;
          int After = 0;
          GLenum First = GL_NO_ERROR;
          int Drain()
          {
            int n = 0;
            for (GLenum e = this->Get(); e != GL_NO_ERROR && n < 64; e = this->Get())
            {
              this->First = n++ == 0 ? e : this->First;
            }
            return n;
          }
        };
        Errors gi, vtk;
        gi.Get = vtk.Get = getError;
        void (*drainAtStart)(vtkObject*, unsigned long, void*, void*) =
          [](vtkObject*, unsigned long, void* client, void*) {
            Errors& e = *static_cast<Errors*>(client);
            e.Before = e.Drain();
          };
        vtkNew<vtkCallbackCommand> onStart;
        onStart->SetCallback(drainAtStart);
        onStart->SetClientData(&gi);
        s.Renderer->AddObserver(vtkCommand::StartEvent, onStart);
        vtkNew<vtkCallbackCommand> onPlainStart;
        onPlainStart->SetCallback(drainAtStart);
        onPlainStart->SetClientData(&vtk);
        Scene plain;
        vtkVoxelGIScenes::AddCornellBox(plain.Renderer);
        plain.Renderer->SetPass(nullptr);
        plain.Render();
        plain.Renderer->AddObserver(vtkCommand::StartEvent, onPlainStart);
        for (const Step& step : steps)
        {
          const std::string before = s.Log.Text;
          plain.Window->SetSize(step.Width, step.Height);
          plain.Window->Render();
          plain.Window->MakeCurrent();
          vtk.After = vtk.Drain();
          s.Window->SetSize(step.Width, step.Height);
          s.Window->Render();
          gl->MakeCurrent();
          gi.First = GL_NO_ERROR;
          gi.After = gi.Drain();
          vtkNew<vtkFloatArray> image;
          const bool read = s.GI->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, image);
          const std::string added = s.Log.Text.substr(before.size());
          std::cout << step.Width << " x " << step.Height << ": GI active " << s.GI->GetGIActive()
                    << ", read back " << read << ", GL errors before / after the renderer "
                    << gi.Before << " / " << gi.After << " (plain VTK " << vtk.Before << " / "
                    << vtk.After << "), messages: " << added << std::endl;
          VOXELGI_CHECK(gi.After == 0 && vtk.After == 0,
            "GL error 0x" << std::hex << gi.First << " left behind by the frame");
          const bool fits = step.Width <= max && step.Height <= max;
          if (fits)
          {
            VOXELGI_CHECK(s.GI->GetGIActive() && read, "GI did not run again: " << added);
            VOXELGI_CHECK(image->GetNumberOfTuples() ==
                static_cast<vtkIdType>(step.Width) * step.Height,
              "read back " << image->GetNumberOfTuples() << " pixels");
            VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
            continue;
          }
          VOXELGI_CHECK(!s.GI->GetGIActive(), "GI ran beyond the texture size limit");
          VOXELGI_CHECK(!read, "GetFloatImage returned an image of a refused frame");
          const std::string size = std::to_string(step.Width) + " x " + std::to_string(step.Height);
          const bool repeated = &step != steps && step.Width == (&step - 1)->Width &&
            step.Height == (&step - 1)->Height;
          if (repeated)
          {
            VOXELGI_CHECK(added.empty(), "the message repeats every frame: " << added);
          }
          else
          {
            VOXELGI_CHECK(added.find(size) != std::string::npos &&
                added.find("GL_MAX_TEXTURE_SIZE " + std::to_string(max)) != std::string::npos &&
                added.find("without GI") != std::string::npos,
              "no clear message naming the size and the limit: " << added);
            VOXELGI_CHECK(
              added.find(size) == added.rfind(size), "more than one message: " << added);
          }
        }
        return EXIT_SUCCESS;
      } },
    { "ActiveCameraObservers",
      [] {
        // Issue 19, crash 2: observers of the renderer's ActiveCameraEvent and of its camera
        // that check the active camera, render another window and remove (and so delete) an
        // actor. The pass must fire none of these events and never show its own cameras
        // through the renderer, even to code that runs while it draws (mapper StartEvent).
        Scene s;
        vtkVoxelGIScenes::AddCornellBox(s.Renderer);
        vtkNew<vtkLight> sun; // a directional light: it gets a shadow map
        sun->SetLightTypeToSceneLight();
        sun->SetPositional(false);
        sun->SetPosition(0.3, 1.0, 0.6);
        sun->SetFocalPoint(0.0, 0.0, 0.0);
        sun->SetIntensity(0.5);
        s.Renderer->AddLight(sun);
        s.GI->SetLightOcclusion(vtkVoxelGIPass::LIGHT_OCCLUSION_SHADOW_MAPS);
        s.Renderer->ResetCamera();
        Scene other;
        AddBox(other.Renderer, 0, 1, 0, 1, 0, 1);
        other.Render();
        struct Watch
        {
          vtkRenderer* Renderer = nullptr;
          vtkCamera* Camera = nullptr;
          vtkRenderWindow* Other = nullptr;
          std::vector<vtkActor*> Victims;
          int CameraEvents = 0;   // ActiveCameraEvent and camera events
          int WrongCamera = 0;    // times anyone saw another camera than the user's
          int MapperStarts = 0;
        } watch;
        watch.Renderer = s.Renderer;
        watch.Camera = s.Renderer->GetActiveCamera();
        watch.Other = other.Window;
        for (int i = 0; i < 3; ++i)
        {
          vtkActor* victim = AddBox(s.Renderer, 0.1 + 0.1 * i, 0.15 + 0.1 * i, 0.1, 0.2, 0.1, 0.2);
          watch.Victims.push_back(victim);
        }
        vtkNew<vtkCallbackCommand> onCamera;
        onCamera->SetClientData(&watch);
        onCamera->SetCallback([](vtkObject*, unsigned long, void* client, void*) {
          Watch& w = *static_cast<Watch*>(client);
          ++w.CameraEvents;
          w.WrongCamera += w.Renderer->GetActiveCamera() != w.Camera ? 1 : 0;
          w.Other->Render();
          if (!w.Victims.empty())
          {
            w.Renderer->RemoveActor(w.Victims.back()); // its last reference: deleted
            w.Victims.pop_back();
          }
        });
        s.Renderer->AddObserver(vtkCommand::ActiveCameraEvent, onCamera);
        watch.Camera->AddObserver(vtkCommand::ModifiedEvent, onCamera);
        vtkNew<vtkCallbackCommand> onMapper;
        onMapper->SetClientData(&watch);
        onMapper->SetCallback([](vtkObject*, unsigned long, void* client, void*) {
          Watch& w = *static_cast<Watch*>(client);
          ++w.MapperStarts;
          w.WrongCamera += w.Renderer->GetActiveCamera() != w.Camera ? 1 : 0;
        });
        vtkActorCollection* actors = s.Renderer->GetActors();
        actors->InitTraversal();
        while (vtkActor* actor = actors->GetNextActor())
        {
          actor->GetMapper()->AddObserver(vtkCommand::StartEvent, onMapper);
        }
        // The user's own changes reach the observers (which delete actors), then frames that
        // voxelize and render shadow maps again: no event may come from the pass (before the
        // fix: two ActiveCameraEvents per voxelization and per shadow-map update, with the
        // pass's camera active, and a crash when the observer deleted an actor then).
        for (int frame = 0; frame < 4; ++frame)
        {
          watch.Camera->Azimuth(5.0);
          s.Renderer->SetActiveCamera(watch.Camera); // the same camera: no event
          const int events = watch.CameraEvents;
          const int starts = watch.MapperStarts;
          if (frame == 2)
          {
            s.GI->Invalidate(); // everything voxelized and lit again
          }
          if (frame == 3)
          {
            sun->SetPosition(0.5, 1.0, 0.2); // shadow maps again
          }
          s.Window->Render();
          std::cout << "frame " << frame << ": GI active " << s.GI->GetGIActive() << ", "
                    << watch.CameraEvents - events << " camera events, "
                    << watch.MapperStarts - starts << " mapper starts, " << watch.WrongCamera
                    << " wrong cameras, " << watch.Victims.size() << " victims left" << std::endl;
          VOXELGI_CHECK(s.GI->GetGIActive(), "GI did not run: " << s.Log.Text);
          VOXELGI_CHECK(s.GI->GetStageRan(vtkVoxelGIPass::STAGE_SHADOW_MAPS) || frame == 1,
            "no shadow maps rendered: the case does not test them");
          VOXELGI_CHECK(watch.CameraEvents == events, "the frame fired camera events");
          VOXELGI_CHECK(watch.MapperStarts > starts || frame == 1, "no mapper rendered");
          VOXELGI_CHECK(watch.WrongCamera == 0, "the pass showed its own camera");
          VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        }
        VOXELGI_CHECK(watch.Victims.empty(), "the observers did not delete the actors");
        return EXIT_SUCCESS;
      } },
    { "ManyActorsAndLights",
      [] {
        Scene s;
        for (int i = 0; i < 1000; ++i)
        {
          AddBox(s.Renderer, i % 10, i % 10 + 0.5, (i / 10) % 10, (i / 10) % 10 + 0.5, i / 100, i / 100 + 0.5);
        }
        for (int i = 0; i < 17; ++i)
        {
          vtkNew<vtkLight> light;
          light->SetLightTypeToSceneLight();
          light->SetPosition(i, 12, -2);
          light->SetFocalPoint(5, 5, 5);
          light->SetIntensity(0.1);
          s.Renderer->AddLight(light);
        }
        s.Render();
        VOXELGI_CHECK(s.GI->GetGIActive(), "GI did not run");
        VOXELGI_CHECK(s.Log.Has("uses the first 16 lights"), "no message about light 17: " << s.Log.Text);
        VOXELGI_CHECK(Bounded(s.GI), "non-finite values");
        return EXIT_SUCCESS;
      } },
  };
  return cases;
}
}

int TestStiffCases(int argc, char* argv[])
{
  return voxelgi_test::RunCases(Cases(), argc, argv);
}
