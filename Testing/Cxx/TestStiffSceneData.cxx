// Stiff cases for the data the pass keeps on the GPU (issue 38): the actors' GPU-resident
// triangles that compute voxelization reads (millions of them, data that changes size at every
// frame, NaN and Inf in the uploaded attributes) and the volumes resampled into the voxels
// (no size, degenerate spacing, NaN scalars, opacity 0, 1 and NaN, and the same for actors).
// Every frame must keep GI on for the valid part of the scene and stay finite and bounded;
// one case per run:
//
//   TestStiffSceneData CASE     (CTest runs each as VoxelGI::Stiff.CASE)

#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkStringOutputWindow.h"
#include "vtkVolume.h"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace
{
using voxelgi_test::Bounded;

const double NaN = std::numeric_limits<double>::quiet_NaN();
const double Inf = std::numeric_limits<double>::infinity();

struct Scene : voxelgi_test::GIWindow
{
  voxelgi_test::Messages Log{ GI };
  Scene()
    : GIWindow(nullptr, 32, 80)
  {
    // A lit box keeps GI running whatever the case does to the rest.
    vtkNew<vtkCubeSource> box;
    box->SetBounds(-1.5, -0.5, -0.5, 0.5, -0.5, 0.5);
    vtkVoxelGIScenes::AddSource(this->Renderer, box, 0.8, 0.7, 0.6);
  }
  /// Renders (camera reset to the finite part of the scene) and checks the frame.
  bool Frame(const std::string& what)
  {
    this->Renderer->ResetCamera(-1.5, 1.5, -1.5, 1.5, -1.5, 1.5);
    this->Window->Render();
    const bool active = this->GI->GetGIActive();
    std::cout << what << ": GI active " << active << std::endl;
    if (!active)
    {
      std::cerr << what << ": GI did not run: " << this->Log.Text << std::endl;
      return false;
    }
    return Bounded(this->GI);
  }
};

vtkSmartPointer<vtkPolyData> Sphere(int resolution)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(1.0, 0.0, 0.0);
  sphere->SetRadius(0.5);
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution);
  sphere->Update();
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->DeepCopy(sphere->GetOutput());
  return poly;
}

vtkActor* AddPolyData(vtkRenderer* renderer, vtkPolyData* poly)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  return actor;
}

/// Occupied voxels of the last voxelization.
int Occupied(vtkVoxelGIPass* gi)
{
  vtkNew<vtkImageData> albedo;
  if (!gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, albedo))
  {
    return -1;
  }
  vtkDataArray* a = albedo->GetPointData()->GetScalars();
  int n = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    n += a->GetComponent(i, 3) > 0 ? 1 : 0;
  }
  return n;
}

/// A volume over [0.5, 1.5] x [-0.5, 0.5]^2 of `dims` points with `scalars` (constant 1 when
/// empty), opacity `alpha` per `unit`.
vtkSmartPointer<vtkVolume> Volume(const int dims[3], const double spacing[3],
  const std::vector<double>& scalars, double alpha, double unit)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(dims[0], dims[1], dims[2]);
  image->SetOrigin(0.5, -0.5, -0.5);
  image->SetSpacing(spacing[0], spacing[1], spacing[2]);
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    values->SetValue(i, scalars.empty() ? 1.f : static_cast<float>(scalars[i % scalars.size()]));
  }
  image->GetPointData()->SetScalars(values);
  return voxelgi_test::UniformVolume(image, alpha, unit, glm::dvec3(0.9, 0.4, 0.1));
}

/// Whether `render` made VTK report an error (captured, not printed).
bool Errors(const std::function<void()>& render)
{
  vtkNew<vtkStringOutputWindow> output;
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  vtkOutputWindow::SetInstance(output);
  // (VTK's logger prints errors to stderr besides the output window)
  const vtkLogger::Verbosity verbosity = vtkLogger::GetCurrentVerbosityCutoff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  render();
  vtkLogger::SetStderrVerbosity(verbosity);
  vtkOutputWindow::SetInstance(previous);
  return output->GetOutput().find("ERROR") != std::string::npos;
}

const voxelgi_test::Cases& Cases()
{
  static const voxelgi_test::Cases cases = {
    { "ResidentTrianglesChangeSize",
      [] {
        // One actor's data replaced at every frame, as a time series does, through sizes that
        // grow, shrink, vanish and come back; the resident buffers must follow each.
        Scene s;
        vtkNew<vtkPolyData> empty;
        vtkNew<vtkPolyData> pointsOnly;
        pointsOnly->SetPoints(Sphere(8)->GetPoints());
        const std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> steps = {
          { "sphere 8", Sphere(8) }, { "sphere 200", Sphere(200) }, { "no points", empty },
          { "points without cells", pointsOnly }, { "sphere 3", Sphere(3) },
          { "sphere 120", Sphere(120) }, { "sphere 8 again", Sphere(8) } };
        vtkActor* actor = AddPolyData(s.Renderer, steps[0].second);
        for (const auto& step : steps)
        {
          vtkPolyDataMapper::SafeDownCast(actor->GetMapper())->SetInputData(step.second);
          VOXELGI_CHECK(s.Frame(step.first), step.first << ": not finite or bounded");
        }
        VOXELGI_CHECK(s.GI->GetAllocatedBytes(vtkVoxelGIPass::RESOURCE_SCENE_BUFFERS) > 0,
          "no resident triangles: the case does not test them");
        // The last frame's voxels are those of a full voxelization of the last data.
        vtkNew<vtkImageData> before;
        VOXELGI_CHECK(s.GI->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, before), "no albedo");
        s.GI->Invalidate();
        VOXELGI_CHECK(s.Frame("voxelized again"), "not finite or bounded");
        vtkNew<vtkImageData> after;
        VOXELGI_CHECK(s.GI->GetVoxelVolume(vtkVoxelGIPass::VOLUME_ALBEDO, after), "no albedo");
        const double d = voxelgi_test::MaxDifference(
          before->GetPointData()->GetScalars(), after->GetPointData()->GetScalars());
        std::cout << "occupied voxels " << Occupied(s.GI) << ", largest albedo difference to a "
                  << "full voxelization " << d << std::endl;
        VOXELGI_CHECK(d == 0.0 && Occupied(s.GI) > 0, "the resident triangles kept older data");
        return EXIT_SUCCESS;
      } },
    { "ResidentAttributesNaN",
      [] {
        // NaN and Inf in the normals and in the scalars a lookup table colours: valid
        // positions, so the same voxels as clean data, and nothing non-finite anywhere.
        Scene clean;
        AddPolyData(clean.Renderer, Sphere(24));
        VOXELGI_CHECK(clean.Frame("clean sphere"), "clean sphere not finite");
        Scene s;
        vtkSmartPointer<vtkPolyData> poly = Sphere(24);
        vtkDataArray* normals = poly->GetPointData()->GetNormals();
        vtkNew<vtkFloatArray> scalars;
        scalars->SetName("value");
        scalars->SetNumberOfTuples(poly->GetNumberOfPoints());
        const double bad[4] = { NaN, Inf, -Inf, 0.5 };
        for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
        {
          scalars->SetValue(i, static_cast<float>(bad[i % 4]));
          if (i % 3 == 0)
          {
            normals->SetTuple3(i, NaN, Inf, 0.0);
          }
        }
        poly->GetPointData()->SetScalars(scalars);
        vtkActor* actor = AddPolyData(s.Renderer, poly);
        actor->GetMapper()->SetScalarRange(0.0, 1.0);
        VOXELGI_CHECK(s.Frame("NaN attributes"), "NaN attributes reached the image");
        VOXELGI_CHECK(s.GI->GetAllocatedBytes(vtkVoxelGIPass::RESOURCE_SCENE_BUFFERS) > 0,
          "no resident triangles: the case does not test them");
        const int got = Occupied(s.GI), expected = Occupied(clean.GI);
        std::cout << "occupied voxels " << got << ", clean data " << expected << std::endl;
        VOXELGI_CHECK(got == expected, "attributes changed which voxels are occupied");
        return EXIT_SUCCESS;
      } },
    { "MillionsOfResidentTriangles",
      [] {
        // Two million triangles through the compute path, and the same through the mappers.
        vtkSmartPointer<vtkPolyData> poly = Sphere(1000);
        std::cout << poly->GetNumberOfCells() << " triangles" << std::endl;
        int occupied[2] = { 0, 0 };
        for (int compute = 1; compute >= 0; --compute)
        {
          Scene s;
          s.GI->SetComputeVoxelization(compute);
          s.GI->SetVoxelResolution(64);
          AddPolyData(s.Renderer, poly);
          VOXELGI_CHECK(s.Frame(compute ? "compute" : "raster"), "not finite or bounded");
          VOXELGI_CHECK(
            (s.GI->GetAllocatedBytes(vtkVoxelGIPass::RESOURCE_SCENE_BUFFERS) > 0) == (compute != 0),
            "the resident triangles do not follow ComputeVoxelization");
          occupied[compute] = Occupied(s.GI);
        }
        std::cout << "occupied voxels: compute " << occupied[1] << ", raster " << occupied[0]
                  << std::endl;
        VOXELGI_CHECK(std::abs(occupied[1] - occupied[0]) <= occupied[0] / 1000 && occupied[0] > 0,
          "the two paths disagree");
        return EXIT_SUCCESS;
      } },
    { "DegenerateVolumes",
      [] {
        // Volumes with no size, one point, a zero, a negative and a NaN spacing: each is
        // resampled or left out with a reason, never breaks the frame.
        struct Variant
        {
          const char* What;
          int Dims[3];
          double Spacing[3];
        };
        const Variant variants[] = { { "no points", { 0, 0, 0 }, { 0.1, 0.1, 0.1 } },
          { "one point", { 1, 1, 1 }, { 0.1, 0.1, 0.1 } },
          { "one point thick", { 11, 1, 11 }, { 0.1, 0.1, 0.1 } },
          { "zero spacing", { 11, 11, 11 }, { 0.1, 0.0, 0.1 } },
          { "negative spacing", { 11, 11, 11 }, { 0.1, -0.1, 0.1 } },
          { "NaN spacing", { 11, 11, 11 }, { 0.1, NaN, 0.1 } } };
        for (const Variant& v : variants)
        {
          Scene s;
          s.Renderer->AddVolume(Volume(v.Dims, v.Spacing, {}, 0.5, 0.1));
          // VTK's volume mapper itself reports some of these: whatever VTK says alone, the
          // pass may say too, and nothing more.
          const bool plainErrs = Errors([&s] {
            s.Renderer->SetPass(nullptr);
            s.Window->Render();
            s.Renderer->SetPass(s.GI);
          });
          bool frames = true;
          const bool errs = Errors([&] {
            frames = s.Frame(v.What) && s.Frame(std::string(v.What) + ", second frame");
          });
          std::cout << v.What << ": errors from VTK alone " << plainErrs << ", with the pass "
                    << errs << std::endl;
          VOXELGI_CHECK(frames, v.What << ": not finite or bounded");
          VOXELGI_CHECK(!errs || plainErrs, v.What << ": the pass reported an error VTK does not");
        }
        return EXIT_SUCCESS;
      } },
    { "VolumeScalarsAndOpacityNaN",
      [] {
        // NaN and Inf scalars; opacity 0, 1 and NaN; a unit distance of 0, NaN and Inf.
        const int dims[3] = { 11, 11, 11 };
        const double spacing[3] = { 0.1, 0.1, 0.1 };
        struct Variant
        {
          const char* What;
          std::vector<double> Scalars;
          double Alpha;
          double Unit;
        };
        const Variant variants[] = { { "NaN and Inf scalars", { NaN, Inf, -Inf, 1.0 }, 0.5, 0.1 },
          { "opacity 0", {}, 0.0, 0.1 }, { "opacity 1", {}, 1.0, 0.1 },
          { "opacity NaN", {}, NaN, 0.1 }, { "unit distance 0", {}, 0.5, 0.0 },
          { "unit distance NaN", {}, 0.5, NaN }, { "unit distance Inf", {}, 0.5, Inf } };
        for (const Variant& v : variants)
        {
          Scene s;
          s.Renderer->AddVolume(Volume(dims, spacing, v.Scalars, v.Alpha, v.Unit));
          VOXELGI_CHECK(s.Frame(v.What), v.What << ": not finite or bounded");
        }
        return EXIT_SUCCESS;
      } },
    { "ActorOpacityExtremes",
      [] {
        // An actor's opacity 0, 1 and NaN (vtkProperty's clamp lets NaN through).
        for (double opacity : { 0.0, 1.0, NaN })
        {
          Scene s;
          vtkActor* actor = AddPolyData(s.Renderer, Sphere(16));
          actor->GetProperty()->SetOpacity(opacity);
          VOXELGI_CHECK(s.Frame("opacity " + std::to_string(opacity)), "opacity " << opacity);
        }
        return EXIT_SUCCESS;
      } },
  };
  return cases;
}
}

int TestStiffSceneData(int argc, char* argv[])
{
  return voxelgi_test::RunCases(Cases(), argc, argv);
}
