#include "FacetNeed.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"

#include <algorithm>
#include <cmath>

namespace voxelgi
{

bool FacetNeed::Needs(vtkActor* actor)
{
  vtkProperty* property = actor ? actor->GetProperty() : nullptr;
  if (property && property->GetInterpolation() == VTK_FLAT)
  {
    return false; // VTK shades each polygon with its own plane
  }
  auto* mapper = actor ? vtkPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
  vtkPolyData* input = mapper ? mapper->GetInput() : nullptr;
  if (!input)
  {
    return true;
  }
  // Entries of inputs gone long ago: a new object never carries an old time.
  if (this->Inputs.size() > 4096)
  {
    this->Inputs.clear();
  }
  Entry& entry = this->Inputs[input];
  if (entry.Time != input->GetMTime())
  {
    entry.Time = input->GetMTime();
    entry.Leans = NormalsLean(input);
  }
  return entry.Leans;
}

bool FacetNeed::NormalsLean(vtkPolyData* polyData)
{
  vtkDataArray* normals = polyData->GetPointData()->GetNormals();
  vtkPoints* points = polyData->GetPoints();
  if (!normals || !points)
  {
    return false; // VTK takes each polygon's normal from its plane
  }
  vtkCellArray* polys = polyData->GetPolys();
  const vtkIdType count = polys ? polys->GetNumberOfCells() : 0;
  if (count == 0)
  {
    // Strips only: not sampled here.
    return polyData->GetNumberOfStrips() > 0;
  }
  const double cosine = std::cos(vtkMath::RadiansFromDegrees(3.0));
  const vtkIdType samples = std::min<vtkIdType>(count, 64);
  vtkNew<vtkIdList> ids;
  for (vtkIdType s = 0; s < samples; ++s)
  {
    polys->GetCellAtId(s * count / samples, ids);
    if (ids->GetNumberOfIds() < 3)
    {
      continue;
    }
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      points->GetPoint(ids->GetId(k), p[k]);
    }
    double a[3], b[3], plane[3];
    vtkMath::Subtract(p[1], p[0], a);
    vtkMath::Subtract(p[2], p[0], b);
    vtkMath::Cross(a, b, plane);
    if (vtkMath::Normalize(plane) == 0.0)
    {
      continue;
    }
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      double n[3];
      normals->GetTuple(ids->GetId(k), n);
      if (vtkMath::Normalize(n) > 0.0 && std::abs(vtkMath::Dot(n, plane)) < cosine)
      {
        return true;
      }
    }
  }
  return false;
}

}
