#include "VoxelGITestUtilities.h"

#include "vtkTesting.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

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

int ImageMatches(int regressionResult)
{
  return (regressionResult == vtkTesting::PASSED || regressionResult == vtkTesting::DO_INTERACTOR)
    ? EXIT_SUCCESS
    : EXIT_FAILURE;
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
