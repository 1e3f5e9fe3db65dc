// Helpers shared by the VoxelGI C++ tests.
#ifndef VoxelGITestUtilities_h
#define VoxelGITestUtilities_h

#include "vtkCallbackCommand.h" // for Messages
#include "vtkNew.h"          // for vtkNew
#include "vtkRenderWindow.h" // for vtkNew
#include "vtkRenderer.h"     // for vtkSmartPointer
#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkVoxelGIPass.h"  // for vtkNew

#include <glm/glm.hpp>

#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <vector>

class vtkActor;
class vtkAlgorithm;
class vtkDataArray;
class vtkFloatArray;
class vtkImageData;
class vtkVolume;

namespace voxelgi_test
{

/// Exact triangle / axis-aligned box overlap (separating axis theorem, Akenine-Moeller),
/// in double precision; touching counts as overlapping.
bool TriangleBoxOverlap(const glm::dvec3& boxCenter, const glm::dvec3& boxHalf,
  const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

/// Exit code of the regression-image comparison of `window` with the baseline given by
/// `-V`: VTK's own comparison (which writes the test and difference images on failure), then
/// a strict one. VTK 9.1's image difference ignores pixels that differ by less than its
/// threshold: a change of up to 74 levels in a channel passed it. The strict comparison
/// fails when more than 0.1 % of the pixels differ by more than 12 levels in a channel or
/// the mean difference exceeds 0.5 levels. Only a passed comparison passes (a run without a
/// baseline is NOT_RUN, which must not count as success).
int ImageMatches(int argc, char* argv[], vtkRenderWindow* window);

/// True when the radiance volume and the composited float image hold only finite values
/// (prints what is not).
bool AllFinite(vtkVoxelGIPass* gi);

/// AllFinite, and the composite within [0, 65504] (prints what is not).
bool Bounded(vtkVoxelGIPass* gi);

/// The composite of the pass's last frame (null when it has none).
vtkSmartPointer<vtkFloatArray> Composite(vtkVoxelGIPass* gi);

/// Largest difference between two images of the same size (1e30 if either is missing or
/// their sizes differ).
double MaxDifference(vtkDataArray* a, vtkDataArray* b);

/// How two RGBA float images of the same size differ over rgb: the largest difference, the
/// mean one and the share of pixels whose largest difference exceeds a threshold (all 1e30
/// when either is empty or their sizes differ).
struct ImageDifference
{
  double Largest = 0.0;
  double Mean = 0.0;
  double Over = 0.0;
};
ImageDifference Differences(vtkDataArray* a, vtkDataArray* b, double threshold);

/// The stages `gi` ran in its last frame, by name, comma-separated.
std::string StagesRan(vtkVoxelGIPass* gi);

/// Cases of a test that runs one case per CTest test, by name.
using Cases = std::map<std::string, std::function<int()>>;
/// Runs the case of `cases` that the command line names into `result` (after printing its
/// name); false when the command line names none.
bool RunNamedCase(const Cases& cases, int argc, char* argv[], int& result);

/// The case the command line names, or every case in turn: EXIT_SUCCESS when all pass.
int RunCases(const Cases& cases, int argc, char* argv[]);

/// A volume over `image` (scalars in [0, 2]) through a vtkSmartVolumeMapper, of colour `rgb`
/// and opacity `alpha` per `unit` of length whatever the scalar.
vtkSmartPointer<vtkVolume> UniformVolume(
  vtkImageData* image, double alpha, double unit, const glm::dvec3& rgb);

/// Prints `value` against its goal, as met or "GOAL NOT MET", with the bound asserted today;
/// false (printed) when it exceeds that bound.
bool Within(const std::string& what, double value, double goal, double asserted);

/// Mean of component `c` of an RGBA float image of width `w` over pixels [x0, x1) x [y0, y1).
double MeanOver(vtkFloatArray* image, int w, int x0, int y0, int x1, int y1, int c);

/// Renders the Cornell box with GI (64^3 voxels, 200 x 200 pixels) in `debugView`, checks
/// that everything stays finite and compares with the test's baseline image.
int CornellRegressionTest(int argc, char* argv[], int debugView);

/// The tests' window showing `renderer` (or, given none, a renderer of its own) through a
/// pass of `resolution`^3 voxels (0: the pass's default), its software profile off: `size` x `size` pixels (200, the
/// image tests' size, by default), `samples` multisamples (negative: VTK's default).
struct GIWindow
{
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkVoxelGIPass> GI;
  explicit GIWindow(vtkRenderer* renderer, int resolution = 64, int size = 200, int samples = -1);

  /// Renders VTK's own image of the renderer in this window: the pass is set aside for the
  /// frame.
  void RenderWithoutGI();
};

/// Collects an object's warnings and errors (observed, so VTK does not print them).
struct Messages
{
  std::string Text;
  int Count = 0; // messages received
  vtkNew<vtkCallbackCommand> Callback;
  explicit Messages(vtkObject* object);
  bool Has(const std::string& part) const { return this->Text.find(part) != std::string::npos; }
};

/// Add an orange sphere and a blue block standing on a grey floor 6 units wide.
void AddSphereAndBlockOnFloor(vtkRenderer* renderer);

/// Add a quad from `o` spanned by p1 - o and p2 - o (normal (p1 - o) x (p2 - o)).
vtkActor* AddQuad(vtkRenderer* renderer, const glm::dvec3& o, const glm::dvec3& p1,
  const glm::dvec3& p2, double r, double g, double b);

/// Add the six inward-facing walls of the box [0, size]^3, grey of albedo `rho`.
std::vector<vtkActor*> AddClosedBox(vtkRenderer* renderer, double size, double rho);

/// Add a closed box [0, size]^3 of black walls that emit radiance `E` (VTK shows them in
/// their ambient colour E).
void AddEmittingBox(vtkRenderer* renderer, double size, double E);

/// The radiance of the floor's voxels (channel `c`, summed over the voxel layers at y = 0)
/// under the world point (x, 0, z) of a radiance volume read back from the pass.
double FloorRadiance(vtkImageData* radiance, double x, double z, int c = 0);

/// Prints a failure and returns false when the condition does not hold.
#define VOXELGI_CHECK(condition, message)                                                    \
  do                                                                                         \
  {                                                                                          \
    if (!(condition))                                                                        \
    {                                                                                        \
      std::cerr << "FAILED: " << #condition << ": " << message << std::endl;                 \
      return EXIT_FAILURE;                                                                   \
    }                                                                                        \
  } while (false)

}

#endif
