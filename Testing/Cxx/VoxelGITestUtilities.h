// Helpers shared by the VoxelGI C++ tests.
#ifndef VoxelGITestUtilities_h
#define VoxelGITestUtilities_h

#include <glm/glm.hpp>

#include <iostream>

class vtkRenderWindow;
class vtkRenderer;

namespace voxelgi_test
{

/// Exact triangle / axis-aligned box overlap (separating axis theorem, Akenine-Moeller),
/// in double precision; touching counts as overlapping.
bool TriangleBoxOverlap(const glm::dvec3& boxCenter, const glm::dvec3& boxHalf,
  const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

/// Exit code for a regression-image result: only a passed comparison passes (a test run
/// without a baseline reports NOT_RUN, which must not count as success).
int ImageMatches(int regressionResult);

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
