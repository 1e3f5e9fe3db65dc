// Conservativeness of the voxelization: every voxel that a triangle touches (exact CPU
// triangle/box overlap) must be occupied, for random, sliver, tiny, large and axis-aligned
// triangles (including ones lying exactly on voxel boundaries). Prints the false-positive
// rate of the conservative rasterization.
#include "VoxelGITestUtilities.h"
#include "vtkVoxelGIPass.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <vector>

namespace
{
using Triangle = std::array<glm::dvec3, 3>;
}

int TestVoxelConservative(int, char*[])
{
  const int res = 32;
  const double padding = 0.05;
  // Two tiny anchor triangles pin the scene bounds to [0, 1]^3, so the grid is known here.
  const double size = 1.0 + 2.0 * padding;
  const double h = size / res;
  const double origin = -padding;

  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(4242);
  auto uniform = [&random](double lo, double hi) {
    random->Next();
    return random->GetRangeValue(lo, hi);
  };
  auto point = [&](double lo, double hi) {
    return glm::dvec3(uniform(lo, hi), uniform(lo, hi), uniform(lo, hi));
  };

  std::vector<Triangle> triangles;
  triangles.push_back({ glm::dvec3(0, 0, 0), glm::dvec3(0.01, 0, 0), glm::dvec3(0, 0.01, 0) });
  triangles.push_back({ glm::dvec3(1, 1, 1), glm::dvec3(0.99, 1, 1), glm::dvec3(1, 0.99, 1) });
  for (int i = 0; i < 120; ++i) // general triangles of all sizes
  {
    const glm::dvec3 c = point(0.1, 0.9);
    const double s = i < 40 ? 0.01 : (i < 80 ? 0.1 : 0.45);
    auto inside = [](const glm::dvec3& v) { return glm::clamp(v, 0.02, 0.98); };
    triangles.push_back({ inside(c + point(-s, s)), inside(c + point(-s, s)), inside(c + point(-s, s)) });
  }
  for (int i = 0; i < 40; ++i) // slivers: a vertex just off the opposite edge
  {
    const glm::dvec3 a = point(0.05, 0.95), b = point(0.05, 0.95);
    const glm::dvec3 mid = 0.5 * (a + b) + point(-1e-3, 1e-3);
    triangles.push_back({ a, b, mid });
  }
  for (int i = 0; i < 30; ++i) // axis-aligned, some exactly on voxel boundaries
  {
    const int axis = i % 3;
    double plane = uniform(0.1, 0.9);
    if (i % 2 == 0)
    {
      plane = origin + h * std::round((plane - origin) / h);
    }
    Triangle t;
    for (auto& v : t)
    {
      v = point(0.05, 0.95);
      v[axis] = plane;
    }
    triangles.push_back(t);
  }

  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  for (const Triangle& t : triangles)
  {
    vtkIdType ids[3];
    for (int k = 0; k < 3; ++k)
    {
      ids[k] = points->InsertNextPoint(t[k].x, t[k].y, t[k].z);
    }
    cells->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(cells);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  voxelgi_test::GIWindow view(renderer, res, 64);
  vtkRenderWindow* window = view.Window;
  vtkVoxelGIPass* gi = view.GI;
  gi->SetGridPadding(padding);
  renderer->ResetCamera();
  // Both paths when the GPU rasterizes conservatively itself; the software one always.
  for (const bool hardware : { true, false })
  {
    gi->SetHardwareConservativeRaster(hardware);
    window->Render();
    VOXELGI_CHECK(gi->GetGIActive(), "GI did not run");
    if (hardware != gi->GetUsedHardwareConservativeRaster())
    {
      std::cout << "no hardware conservative rasterization on this GPU" << std::endl;
      continue;
    }
    double gridOrigin[3];
    gi->GetGridOrigin(gridOrigin);
    VOXELGI_CHECK(gi->GetGridResolution() == res, "resolution " << gi->GetGridResolution());
    VOXELGI_CHECK(std::abs(gi->GetGridVoxelSize() - h) < 1e-12, "voxel size " << gi->GetGridVoxelSize());
    VOXELGI_CHECK(std::abs(gridOrigin[0] - origin) < 1e-12, "origin " << gridOrigin[0]);

    vtkNew<vtkImageData> counts;
    VOXELGI_CHECK(gi->GetVoxelVolume(vtkVoxelGIPass::VOLUME_COUNT, counts), "no count volume");
    vtkDataArray* occupancy = counts->GetPointData()->GetScalars();

    std::vector<char> expected(static_cast<std::size_t>(res) * res * res, 0);
    const glm::dvec3 half(0.5 * h);
    for (const Triangle& t : triangles)
    {
      glm::ivec3 lo(res), hi(-1);
      for (const auto& v : t)
      {
        const glm::dvec3 g = (v - glm::dvec3(origin)) / h;
        lo = glm::min(lo, glm::ivec3(glm::floor(g)) - 1);
        hi = glm::max(hi, glm::ivec3(glm::floor(g)) + 1);
      }
      lo = glm::clamp(lo, glm::ivec3(0), glm::ivec3(res - 1));
      hi = glm::clamp(hi, glm::ivec3(0), glm::ivec3(res - 1));
      for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
          for (int x = lo.x; x <= hi.x; ++x)
          {
            const glm::dvec3 center = glm::dvec3(origin) + (glm::dvec3(x, y, z) + 0.5) * h;
            if (voxelgi_test::TriangleBoxOverlap(center, half, t[0], t[1], t[2]))
            {
              expected[x + res * (y + res * z)] = 1;
            }
          }
    }

    long touched = 0, missed = 0, occupied = 0, extra = 0;
    for (std::size_t i = 0; i < expected.size(); ++i)
    {
      const bool gpu = occupancy->GetTuple1(static_cast<vtkIdType>(i)) > 0;
      touched += expected[i];
      occupied += gpu;
      missed += (expected[i] && !gpu);
      extra += (!expected[i] && gpu);
    }
    std::cout << (hardware ? "hardware" : "software") << " conservative rasterization, "
              << triangles.size() << " triangles: " << touched << " voxels touched, " << occupied
              << " occupied, " << missed << " missed, false-positive rate "
              << (occupied ? 100.0 * extra / occupied : 0.0) << "%" << std::endl;
    VOXELGI_CHECK(touched > 1000, "the triangles touch too few voxels to test anything");
    VOXELGI_CHECK(missed == 0, missed << " touched voxels are missing");
    // Conservative, but not wildly so.
    VOXELGI_CHECK(extra < occupied / 2, "false positives " << extra << " of " << occupied);
  }
  return EXIT_SUCCESS;
}
