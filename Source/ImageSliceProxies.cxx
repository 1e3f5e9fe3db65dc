#include "ImageSliceProxies.h"

#include "SceneScan.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageProperty.h"
#include "vtkImageSlice.h"
#include "vtkImageSliceMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkScalarsToColors.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace voxelgi
{

namespace
{
/// What the proxy is built from: the slice's signature, its property and lookup table.
vtkMTimeType SliceTime(vtkImageSlice* slice)
{
  vtkMTimeType t = SceneScan::PropSignature(slice);
  if (vtkImageProperty* property = slice->GetProperty())
  {
    t = std::max(t, property->GetMTime());
    if (vtkScalarsToColors* lut = property->GetLookupTable())
    {
      t = std::max(t, lut->GetMTime());
    }
  }
  return t;
}

/// The colours VTK shows for `values` (the slice's scalars): through the property's lookup
/// table, over its own range or the window's, or window and level per component.
vtkSmartPointer<vtkUnsignedCharArray> DisplayedColors(vtkDataArray* values, vtkImageProperty* property)
{
  const double window = property ? property->GetColorWindow() : 255.0;
  const double level = property ? property->GetColorLevel() : 127.5;
  const double low = level - 0.5 * window;
  vtkScalarsToColors* lut = property ? property->GetLookupTable() : nullptr;
  if (lut)
  {
    vtkSmartPointer<vtkScalarsToColors> table;
    table.TakeReference(lut->NewInstance());
    table->DeepCopy(lut);
    if (!property->GetUseLookupTableScalarRange())
    {
      table->SetRange(low, low + window);
    }
    vtkSmartPointer<vtkUnsignedCharArray> mapped;
    mapped.TakeReference(table->MapScalars(values, VTK_COLOR_MODE_MAP_SCALARS, -1, VTK_RGB));
    return mapped;
  }
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(values->GetNumberOfTuples());
  const int components = values->GetNumberOfComponents();
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      // One or two components (luminance, alpha): grey.
      const double v = values->GetComponent(i, components >= 3 ? c : 0);
      const double t = window != 0.0 ? (v - low) / window : (v >= level ? 1.0 : 0.0);
      const double shown = std::isfinite(t) ? std::min(std::max(t, 0.0), 1.0) : 0.0;
      colors->SetValue(3 * i + c, static_cast<unsigned char>(std::lround(255.0 * shown)));
    }
  }
  return colors;
}
}

std::string ImageSliceProxies::LeftOutReason(vtkImageSlice* slice)
{
  vtkImageMapper3D* mapper = slice->GetMapper();
  if (!vtkImageSliceMapper::SafeDownCast(mapper))
  {
    return std::string(slice->GetClassName()) + " with a " +
      (mapper ? mapper->GetClassName() : "null mapper") +
      " (only vtkImageSliceMapper slices are voxelized)";
  }
  if (slice->GetProperty() && slice->GetProperty()->GetOpacity() < 1.0)
  {
    return std::string(slice->GetClassName()) + " (translucent)";
  }
  return std::string();
}

vtkActor* ImageSliceProxies::Update(vtkImageSlice* slice, std::string& reason)
{
  Proxy& proxy = this->Proxies[slice];
  const vtkMTimeType time = SliceTime(slice);
  if (!proxy.Actor || proxy.Synced != time)
  {
    if (!proxy.Actor)
    {
      proxy.Actor = vtkSmartPointer<vtkActor>::New();
    }
    if (!Build(slice, proxy.Actor, reason))
    {
      this->Proxies.erase(slice);
      return nullptr;
    }
    proxy.Synced = time;
  }
  return proxy.Actor;
}

bool ImageSliceProxies::Build(vtkImageSlice* slice, vtkActor* proxy, std::string& reason)
{
  auto* mapper = vtkImageSliceMapper::SafeDownCast(slice->GetMapper());
  mapper->Update();
  vtkImageData* image = mapper->GetInput();
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!scalars)
  {
    reason = std::string(slice->GetClassName()) + " (no image scalars)";
    return false;
  }
  // The displayed slice: a 2D image's extent, or one slice of a 3D image across the mapper's
  // orientation, within an image actor's display extent.
  int extent[6];
  image->GetExtent(extent);
  int flat = -1;
  for (int a = 0; a < 3; ++a)
  {
    flat = (flat < 0 && extent[2 * a] == extent[2 * a + 1]) ? a : flat;
  }
  if (flat < 0)
  {
    flat = mapper->GetOrientation();
    const int k = std::min(std::max(mapper->GetSliceNumber(), extent[2 * flat]), extent[2 * flat + 1]);
    extent[2 * flat] = extent[2 * flat + 1] = k;
  }
  if (auto* actor = vtkImageActor::SafeDownCast(slice))
  {
    const int* display = actor->GetDisplayExtent();
    if (display[0] <= display[1])
    {
      for (int i = 0; i < 6; i += 2)
      {
        extent[i] = std::max(extent[i], display[i]);
        extent[i + 1] = std::min(extent[i + 1], display[i + 1]);
      }
    }
  }
  const int u = (flat + 1) % 3, v = (flat + 2) % 3; // the slice's axes, right-handed
  const int nu = extent[2 * u + 1] - extent[2 * u] + 1, nv = extent[2 * v + 1] - extent[2 * v] + 1;
  if (nu < 2 || nv < 2 || extent[2 * flat] > extent[2 * flat + 1])
  {
    reason = std::string(slice->GetClassName()) + " (a slice without area)";
    return false;
  }

  // Texture: the slice's values in (u, v) order, coloured as VTK shows them.
  vtkSmartPointer<vtkDataArray> values;
  values.TakeReference(scalars->NewInstance());
  values->SetNumberOfComponents(scalars->GetNumberOfComponents());
  values->SetNumberOfTuples(static_cast<vtkIdType>(nu) * nv);
  int ijk[3];
  ijk[flat] = extent[2 * flat];
  for (int j = 0; j < nv; ++j)
  {
    for (int i = 0; i < nu; ++i)
    {
      ijk[u] = extent[2 * u] + i;
      ijk[v] = extent[2 * v] + j;
      values->SetTuple(static_cast<vtkIdType>(j) * nu + i, image->ComputePointId(ijk), scalars);
    }
  }
  vtkNew<vtkImageData> texels;
  texels->SetDimensions(nu, nv, 1);
  texels->GetPointData()->SetScalars(DisplayedColors(values, slice->GetProperty()));
  vtkNew<vtkTexture> texture;
  texture->SetInputData(texels);
  texture->SetInterpolate(slice->GetProperty() &&
    slice->GetProperty()->GetInterpolationType() != VTK_NEAREST_INTERPOLATION);
  texture->RepeatOff();
  texture->EdgeClampOn();

  // Quad through the first and last points' centres (VTK draws the slice so, without a
  // border), texture coordinates on the texel centres.
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetNumberOfComponents(2);
  for (int corner = 0; corner < 4; ++corner)
  {
    const int cu = corner & 1, cv = corner >> 1;
    double index[3];
    index[flat] = extent[2 * flat];
    index[u] = extent[2 * u + cu];
    index[v] = extent[2 * v + cv];
    double xyz[3];
    image->TransformContinuousIndexToPhysicalPoint(index, xyz);
    points->InsertNextPoint(xyz);
    const float tc[2] = { (cu ? nu - 0.5f : 0.5f) / nu, (cv ? nv - 0.5f : 0.5f) / nv };
    tcoords->InsertNextTuple(tc);
  }
  vtkNew<vtkPolyData> quad;
  quad->SetPoints(points);
  quad->GetPointData()->SetTCoords(tcoords);
  vtkNew<vtkCellArray> cells;
  const vtkIdType ids[4] = { 0, 1, 3, 2 };
  cells->InsertNextCell(4, ids);
  quad->SetPolys(cells);

  vtkNew<vtkPolyDataMapper> quadMapper;
  quadMapper->SetInputData(quad);
  quadMapper->ScalarVisibilityOff();
  proxy->SetMapper(quadMapper);
  proxy->SetTexture(texture);
  // Albedo: the displayed colour (the texture over white).
  proxy->GetProperty()->SetColor(1.0, 1.0, 1.0);
  proxy->GetProperty()->SetSpecular(0.0);
  vtkNew<vtkMatrix4x4> matrix;
  matrix->DeepCopy(slice->GetMatrix());
  proxy->SetUserMatrix(matrix);
  proxy->Modified();
  return true;
}

void ImageSliceProxies::Retain(const std::set<vtkProp*>& kept)
{
  for (auto it = this->Proxies.begin(); it != this->Proxies.end();)
  {
    it = kept.count(it->first) ? std::next(it) : this->Proxies.erase(it);
  }
}

}
