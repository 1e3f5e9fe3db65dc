#include "GridView.h"

#include "VoxelGrid.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkRenderer.h"

namespace voxelgi
{

namespace
{
void ToColumnMajor(vtkMatrix4x4* m, float columnMajor[16])
{
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      columnMajor[c * 4 + r] = static_cast<float>(m->GetElement(r, c));
    }
  }
}
}

void GridFromNDC(
  vtkRenderer* renderer, const VoxelGrid& grid, float columnMajor[16], float ndcFromGrid[16])
{
  int width = 0, height = 0, x = 0, y = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  const double aspect = height > 0 ? static_cast<double>(width) / height : 1.0;
  vtkNew<vtkMatrix4x4> worldFromNDC;
  worldFromNDC->DeepCopy(
    renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(aspect, -1, 1));
  worldFromNDC->Invert();
  vtkNew<vtkMatrix4x4> gridFromWorld;
  for (int a = 0; a < 3; ++a)
  {
    gridFromWorld->SetElement(a, a, 1.0 / grid.VoxelSize);
    gridFromWorld->SetElement(a, 3, -grid.Origin[a] / grid.VoxelSize);
  }
  vtkNew<vtkMatrix4x4> gridFromNDC;
  vtkMatrix4x4::Multiply4x4(gridFromWorld, worldFromNDC, gridFromNDC);
  ToColumnMajor(gridFromNDC, columnMajor);
  if (ndcFromGrid)
  {
    gridFromNDC->Invert();
    ToColumnMajor(gridFromNDC, ndcFromGrid);
  }
}

void NormalToGrid(vtkRenderer* renderer, float columnMajor[9])
{
  vtkMatrix4x4* view = renderer->GetActiveCamera()->GetViewTransformMatrix();
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      // inverse of the rotation = its transpose
      columnMajor[c * 3 + r] = static_cast<float>(view->GetElement(c, r));
    }
  }
}

}
