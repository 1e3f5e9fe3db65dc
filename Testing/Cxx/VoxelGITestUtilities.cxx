#include "VoxelGITestUtilities.h"

#include "vtkVoxelGIEGLRenderWindow.h"
#include "vtkVoxelGIPass.h"
#include "vtkVoxelGIScenes.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkPNGReader.h"
#include "vtkRegressionTestImage.h"
#include "vtkWindowToImageFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkSphereSource.h"
#include "vtkObjectFactory.h"
#include "vtkTesting.h"
#include "vtkVersionMacros.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace
{
// With VOXELGI_EGL set, every vtkRenderWindow the tests create is a headless EGL window, so
// the same tests run on GPU machines without an X server.
class EGLWindowFactory : public vtkObjectFactory
{
public:
  static EGLWindowFactory* New()
  {
    auto* factory = new EGLWindowFactory;
    factory->InitializeObjectBase();
    return factory;
  }
  const char* GetVTKSourceVersion() override { return VTK_SOURCE_VERSION; }
  const char* GetDescription() override { return "VoxelGI tests: headless EGL windows"; }

private:
  EGLWindowFactory()
  {
    this->RegisterOverride("vtkRenderWindow", "vtkVoxelGIEGLRenderWindow", "EGL window", 1,
      []() -> vtkObject* { return vtkVoxelGIEGLRenderWindow::New(); });
  }
};

struct EGLWindowRegistration
{
  EGLWindowRegistration()
  {
    if (std::getenv("VOXELGI_EGL"))
    {
      auto* factory = EGLWindowFactory::New();
      vtkObjectFactory::RegisterFactory(factory);
      factory->Delete();
      vtkObjectFactory::SetAllEnableFlags(0, "vtkRenderWindow");
      vtkObjectFactory::SetAllEnableFlags(1, "vtkRenderWindow", "vtkVoxelGIEGLRenderWindow");
    }
  }
} eglWindowRegistration;
}

namespace voxelgi_test
{

namespace
{
// Project the triangle and the box on `axis`; separated if the intervals do not meet.
bool Separated(const glm::dvec3& axis, const glm::dvec3& v0, const glm::dvec3& v1,
  const glm::dvec3& v2, const glm::dvec3& half)
{
  const double p0 = glm::dot(axis, v0), p1 = glm::dot(axis, v1), p2 = glm::dot(axis, v2);
  const double r = half.x * std::abs(axis.x) + half.y * std::abs(axis.y) + half.z * std::abs(axis.z);
  return std::min({ p0, p1, p2 }) > r || std::max({ p0, p1, p2 }) < -r;
}
}

int ImageMatches(int argc, char* argv[], vtkRenderWindow* window)
{
  const int result = vtkRegressionTestImage(window);
  if (result == vtkTesting::DO_INTERACTOR)
  {
    return EXIT_SUCCESS;
  }
  if (result != vtkTesting::PASSED)
  {
    return EXIT_FAILURE;
  }
  const char* baseline = nullptr;
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "-V")
    {
      baseline = argv[i + 1];
    }
  }
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(baseline);
  reader->Update();
  vtkNew<vtkWindowToImageFilter> grab; // what VTK's comparison read: the back buffer
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  vtkDataArray* expected = reader->GetOutput()->GetPointData()->GetScalars();
  vtkDataArray* actual = grab->GetOutput()->GetPointData()->GetScalars();
  if (!expected || !actual || expected->GetNumberOfTuples() != actual->GetNumberOfTuples() ||
    expected->GetNumberOfComponents() < 3)
  {
    std::cerr << "FAILED: the baseline " << (baseline ? baseline : "(none)")
              << " could not be read or has another size" << std::endl;
    return EXIT_FAILURE;
  }
  double sum = 0.0;
  vtkIdType over = 0;
  const vtkIdType n = actual->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double largest = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      const double d = std::abs(actual->GetComponent(i, c) - expected->GetComponent(i, c));
      sum += d;
      largest = std::max(largest, d);
    }
    over += largest > 12.0 ? 1 : 0;
  }
  const double mean = sum / (3.0 * static_cast<double>(n));
  std::cout << "strict image comparison: mean difference " << mean << " levels, "
            << 100.0 * static_cast<double>(over) / static_cast<double>(n)
            << " % of pixels differ by more than 12 levels" << std::endl;
  if (mean > 0.5 || over > n / 1000)
  {
    std::cerr << "FAILED: the image differs from its baseline (VTK's threshold hid it)"
              << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}

bool Bounded(vtkVoxelGIPass* gi)
{
  if (!AllFinite(gi))
  {
    return false;
  }
  vtkNew<vtkFloatArray> image;
  if (gi->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, image))
  {
    for (vtkIdType i = 0; i < image->GetNumberOfValues(); ++i)
    {
      if (image->GetValue(i) < 0.0f || image->GetValue(i) > 65504.0f)
      {
        std::cerr << "composite value " << image->GetValue(i) << " out of [0, 65504]" << std::endl;
        return false;
      }
    }
  }
  return true;
}

bool RunNamedCase(const Cases& cases, int argc, char* argv[], int& result)
{
  // The test driver passes the test name first; a case name may follow.
  for (int i = 1; i < argc; ++i)
  {
    auto found = cases.find(argv[i]);
    if (found != cases.end())
    {
      std::cout << "case " << found->first << std::endl;
      result = found->second();
      return true;
    }
  }
  return false;
}

int RunCases(const Cases& cases, int argc, char* argv[])
{
  int result = EXIT_FAILURE;
  if (RunNamedCase(cases, argc, argv, result))
  {
    return result;
  }
  int failures = 0;
  for (const auto& c : cases)
  {
    std::cout << "case " << c.first << std::endl;
    failures += c.second() == EXIT_SUCCESS ? 0 : 1;
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

vtkSmartPointer<vtkVolume> UniformVolume(
  vtkImageData* image, double alpha, double unit, const glm::dvec3& rgb)
{
  vtkNew<vtkSmartVolumeMapper> mapper;
  mapper->SetInputData(image);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, alpha);
  opacity->AddPoint(2.0, alpha);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, rgb.x, rgb.y, rgb.z);
  color->AddRGBPoint(2.0, rgb.x, rgb.y, rgb.z);
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  volume->GetProperty()->SetScalarOpacity(opacity);
  volume->GetProperty()->SetColor(color);
  volume->GetProperty()->SetScalarOpacityUnitDistance(unit);
  return volume;
}

bool Within(const std::string& what, double value, double goal, double asserted)
{
  std::cout << what << ": " << value << (value <= goal ? " (goal " : " (GOAL NOT MET: goal ")
            << goal << ", asserted " << asserted << ")" << std::endl;
  if (value > asserted)
  {
    std::cerr << "FAILED: " << what << " " << value << " above " << asserted << std::endl;
    return false;
  }
  return true;
}

bool AllFinite(vtkVoxelGIPass* gi)
{
  vtkNew<vtkImageData> radiance;
  if (gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_RADIANCE, radiance))
  {
    vtkDataArray* values = radiance->GetPointData()->GetScalars();
    for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
    {
      if (!std::isfinite(values->GetVariantValue(i).ToDouble()))
      {
        std::cerr << "non-finite radiance at voxel value " << i << std::endl;
        return false;
      }
    }
  }
  vtkNew<vtkFloatArray> image;
  if (gi->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, image))
  {
    for (vtkIdType i = 0; i < image->GetNumberOfValues(); ++i)
    {
      if (!std::isfinite(image->GetValue(i)))
      {
        std::cerr << "non-finite composite pixel value " << i << std::endl;
        return false;
      }
    }
  }
  return true;
}

double MeanOver(vtkFloatArray* image, int w, int x0, int y0, int x1, int y1, int c)
{
  double sum = 0.0;
  int n = 0;
  for (int y = y0; y < y1; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      sum += image->GetComponent(static_cast<vtkIdType>(y) * w + x, c);
      ++n;
    }
  }
  return n ? sum / n : 0.0;
}

vtkActor* AddQuad(vtkRenderer* renderer, const glm::dvec3& o, const glm::dvec3& p1,
  const glm::dvec3& p2, double r, double g, double b)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(o.x, o.y, o.z);
  plane->SetPoint1(p1.x, p1.y, p1.z);
  plane->SetPoint2(p2.x, p2.y, p2.z);
  return vtkVoxelGIScenes::AddSource(renderer, plane, r, g, b);
}

std::vector<vtkActor*> AddClosedBox(vtkRenderer* renderer, double size, double rho)
{
  const double S = size;
  const glm::dvec3 quads[6][3] = { { { 0, 0, 0 }, { 0, 0, S }, { S, 0, 0 } },
    { { 0, S, 0 }, { S, S, 0 }, { 0, S, S } }, { { 0, 0, 0 }, { S, 0, 0 }, { 0, S, 0 } },
    { { 0, 0, S }, { 0, S, S }, { S, 0, S } }, { { 0, 0, 0 }, { 0, S, 0 }, { 0, 0, S } },
    { { S, 0, 0 }, { S, 0, S }, { S, S, 0 } } };
  std::vector<vtkActor*> walls;
  for (const auto& q : quads)
  {
    walls.push_back(AddQuad(renderer, q[0], q[1], q[2], rho, rho, rho));
  }
  return walls;
}

void AddEmittingBox(vtkRenderer* renderer, double size, double E)
{
  for (vtkActor* wall : AddClosedBox(renderer, size, 0.0))
  {
    wall->GetProperty()->SetAmbient(1.0);
    wall->GetProperty()->SetAmbientColor(E, E, E);
    wall->GetProperty()->SetDiffuse(0.0);
    vtkVoxelGIPass::SetPropEmission(wall, E, E, E);
  }
}

double FloorRadiance(vtkImageData* radiance, double x, double z, int c)
{
  const double* origin = radiance->GetOrigin(); // the first voxel's centre
  const double h = radiance->GetSpacing()[0];
  const int* dims = radiance->GetDimensions();
  const int i = static_cast<int>(std::lround((x - origin[0]) / h));
  const int k = static_cast<int>(std::lround((z - origin[2]) / h));
  const int j0 = static_cast<int>(std::lround((0.0 - origin[1]) / h));
  double sum = 0.0;
  for (int j = std::max(j0 - 2, 0); j <= std::min(j0 + 2, dims[1] - 1); ++j)
  {
    int ijk[3] = { i, j, k };
    sum += radiance->GetPointData()->GetScalars()->GetComponent(radiance->ComputePointId(ijk), c);
  }
  return sum;
}

vtkSmartPointer<vtkFloatArray> Composite(vtkVoxelGIPass* gi)
{
  auto image = vtkSmartPointer<vtkFloatArray>::New();
  return gi->GetFloatImage(vtkVoxelGIPass::IMAGE_COMPOSITE, image) ? image : nullptr;
}

double MaxDifference(vtkDataArray* a, vtkDataArray* b)
{
  if (!a || !b || a->GetNumberOfValues() != b->GetNumberOfValues() ||
    a->GetNumberOfComponents() != b->GetNumberOfComponents())
  {
    return 1e30;
  }
  double d = 0.0;
  for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < a->GetNumberOfComponents(); ++c)
    {
      d = std::max(d, std::abs(a->GetComponent(t, c) - b->GetComponent(t, c)));
    }
  }
  return d;
}

ImageDifference Differences(vtkDataArray* a, vtkDataArray* b, double threshold)
{
  ImageDifference difference;
  const vtkIdType pixels = a && b ? a->GetNumberOfTuples() : 0;
  if (pixels == 0 || pixels != b->GetNumberOfTuples())
  {
    difference.Largest = difference.Mean = difference.Over = 1e30;
    return difference;
  }
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      const double d = std::abs(a->GetComponent(p, c) - b->GetComponent(p, c));
      worst = std::max(worst, d);
      difference.Mean += d / 3.0;
    }
    difference.Largest = std::max(difference.Largest, worst);
    difference.Over += worst > threshold ? 1.0 : 0.0;
  }
  difference.Mean /= pixels;
  difference.Over /= pixels;
  return difference;
}

std::string StagesRan(vtkVoxelGIPass* gi)
{
  std::string ran;
  for (int stage = 0; stage < vtkVoxelGIPass::NUMBER_OF_STAGES; ++stage)
  {
    if (gi->GetStageRan(stage))
    {
      ran += std::string(ran.empty() ? "" : ",") + vtkVoxelGIPass::GetStageName(stage);
    }
  }
  return ran;
}

GIWindow::GIWindow(vtkRenderer* renderer, int resolution, int size, int samples)
  : Renderer(renderer)
{
  if (!this->Renderer)
  {
    this->Renderer = vtkSmartPointer<vtkRenderer>::New();
  }
  this->Window->SetSize(size, size);
  if (samples >= 0)
  {
    this->Window->SetMultiSamples(samples);
  }
  this->Window->AddRenderer(this->Renderer);
  // The tests measure the settings themselves, also where OpenGL runs on the CPU.
  this->GI->SetSoftwareProfileToOff();
  if (resolution > 0)
  {
    this->GI->SetVoxelResolution(resolution);
  }
  this->Renderer->SetPass(this->GI);
}

void GIWindow::RenderWithoutGI()
{
  this->Renderer->SetPass(nullptr);
  this->Window->Render();
  this->Renderer->SetPass(this->GI);
}

//------------------------------------------------------------------------------
Messages::Messages(vtkObject* object)
{
  this->Callback->SetClientData(this);
  this->Callback->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
    auto* messages = static_cast<Messages*>(client);
    messages->Text += static_cast<const char*>(data);
    ++messages->Count;
  });
  object->AddObserver(vtkCommand::WarningEvent, this->Callback);
  object->AddObserver(vtkCommand::ErrorEvent, this->Callback);
}

void AddSphereAndBlockOnFloor(vtkRenderer* renderer)
{
  using glm::dvec3;
  AddQuad(renderer, dvec3(-3, 0, -3), dvec3(-3, 0, 3), dvec3(3, 0, -3), 0.8, 0.8, 0.8);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(-0.8, 0.8, 0.0);
  sphere->SetRadius(0.8);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  vtkVoxelGIScenes::AddSource(renderer, sphere, 0.9, 0.6, 0.1);
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(0.4, 1.6, 0.0, 1.2, -0.8, 0.4);
  vtkVoxelGIScenes::AddSource(renderer, cube, 0.2, 0.5, 0.9);
}

int CornellRegressionTest(int argc, char* argv[], int debugView)
{
  vtkNew<vtkRenderer> renderer;
  vtkVoxelGIScenes::AddCornellBox(renderer);
  GIWindow view(renderer);
  view.GI->SetDebugView(debugView);
  view.Window->Render();
  if (!view.GI->GetGIActive() || !AllFinite(view.GI))
  {
    std::cerr << "GI did not run, or produced non-finite values" << std::endl;
    return EXIT_FAILURE;
  }
  return ImageMatches(argc, argv, view.Window);
}

bool TriangleBoxOverlap(const glm::dvec3& boxCenter, const glm::dvec3& boxHalf,
  const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
  const glm::dvec3 v0 = a - boxCenter, v1 = b - boxCenter, v2 = c - boxCenter;
  const glm::dvec3 e[3] = { v1 - v0, v2 - v1, v0 - v2 };
  const glm::dvec3 unit[3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  for (const auto& u : unit)
  {
    for (const auto& edge : e)
    {
      const glm::dvec3 axis = glm::cross(u, edge);
      if (glm::dot(axis, axis) > 0.0 && Separated(axis, v0, v1, v2, boxHalf))
      {
        return false;
      }
    }
    if (Separated(u, v0, v1, v2, boxHalf))
    {
      return false;
    }
  }
  const glm::dvec3 n = glm::cross(e[0], e[1]);
  return !(glm::dot(n, n) > 0.0 && Separated(n, v0, v1, v2, boxHalf));
}

}
