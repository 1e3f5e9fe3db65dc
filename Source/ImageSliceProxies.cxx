#include "ImageSliceProxies.h"

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
/// What the proxy is built from: the slice's signature (as the scan found it), its property
/// and lookup table.
vtkMTimeType SliceTime(vtkImageSlice* slice, vtkMTimeType signature)
{
  vtkMTimeType t = signature;
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

vtkActor* ImageSliceProxies::Update(
  vtkImageSlice* slice, vtkMTimeType signature, std::string& reason)
{
  Proxy& proxy = this->Proxies[slice];
  const vtkMTimeType time = SliceTime(slice, signature);
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
  if (!image || !image->GetPointData()->GetScalars())
  {
    reason = std::string(slice->GetClassName()) + " (no image scalars)";
    return false;
  }
  SliceExtent extent;
  if (!DisplayedExtent(slice, image, extent))
  {
    reason = std::string(slice->GetClassName()) + " (a slice without area)";
    return false;
  }
  vtkNew<vtkPolyDataMapper> quadMapper;
  quadMapper->SetInputData(Quad(image, extent));
  quadMapper->ScalarVisibilityOff();
  proxy->SetMapper(quadMapper);
  proxy->SetTexture(Texture(slice, image, extent));
  // Albedo: the displayed colour (the texture over white).
  proxy->GetProperty()->SetColor(1.0, 1.0, 1.0);
  proxy->GetProperty()->SetSpecular(0.0);
  vtkNew<vtkMatrix4x4> matrix;
  matrix->DeepCopy(slice->GetMatrix());
  proxy->SetUserMatrix(matrix);
  proxy->Modified();
  return true;
}

bool ImageSliceProxies::DisplayedExtent(vtkImageSlice* slice, vtkImageData* image, SliceExtent& e)
{
  // A 2D image's extent, or one slice of a 3D image across the mapper's orientation, within
  // an image actor's display extent.
  auto* mapper = vtkImageSliceMapper::SafeDownCast(slice->GetMapper());
  int* extent = e.Extent;
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
  e.Flat = flat;
  e.U = (flat + 1) % 3; // the slice's axes, right-handed
  e.V = (flat + 2) % 3;
  e.NU = extent[2 * e.U + 1] - extent[2 * e.U] + 1;
  e.NV = extent[2 * e.V + 1] - extent[2 * e.V] + 1;
  return e.NU >= 2 && e.NV >= 2 && extent[2 * flat] <= extent[2 * flat + 1];
}

vtkSmartPointer<vtkTexture> ImageSliceProxies::Texture(
  vtkImageSlice* slice, vtkImageData* image, const SliceExtent& e)
{
  // The slice's values in (u, v) order, coloured as VTK shows them.
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  vtkSmartPointer<vtkDataArray> values;
  values.TakeReference(scalars->NewInstance());
  values->SetNumberOfComponents(scalars->GetNumberOfComponents());
  values->SetNumberOfTuples(static_cast<vtkIdType>(e.NU) * e.NV);
  int ijk[3];
  ijk[e.Flat] = e.Extent[2 * e.Flat];
  for (int j = 0; j < e.NV; ++j)
  {
    for (int i = 0; i < e.NU; ++i)
    {
      ijk[e.U] = e.Extent[2 * e.U] + i;
      ijk[e.V] = e.Extent[2 * e.V] + j;
      values->SetTuple(static_cast<vtkIdType>(j) * e.NU + i, image->ComputePointId(ijk), scalars);
    }
  }
  vtkNew<vtkImageData> texels;
  texels->SetDimensions(e.NU, e.NV, 1);
  texels->GetPointData()->SetScalars(DisplayedColors(values, slice->GetProperty()));
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(texels);
  texture->SetInterpolate(slice->GetProperty() &&
    slice->GetProperty()->GetInterpolationType() != VTK_NEAREST_INTERPOLATION);
  texture->RepeatOff();
  texture->EdgeClampOn();
  return texture;
}

vtkSmartPointer<vtkPolyData> ImageSliceProxies::Quad(vtkImageData* image, const SliceExtent& e)
{
  // Through the first and last points' centres (VTK draws the slice so, without a border),
  // texture coordinates on the texel centres.
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetNumberOfComponents(2);
  for (int corner = 0; corner < 4; ++corner)
  {
    const int cu = corner & 1, cv = corner >> 1;
    double index[3];
    index[e.Flat] = e.Extent[2 * e.Flat];
    index[e.U] = e.Extent[2 * e.U + cu];
    index[e.V] = e.Extent[2 * e.V + cv];
    double xyz[3];
    image->TransformContinuousIndexToPhysicalPoint(index, xyz);
    points->InsertNextPoint(xyz);
    const float tc[2] = { (cu ? e.NU - 0.5f : 0.5f) / e.NU, (cv ? e.NV - 0.5f : 0.5f) / e.NV };
    tcoords->InsertNextTuple(tc);
  }
  auto quad = vtkSmartPointer<vtkPolyData>::New();
  quad->SetPoints(points);
  quad->GetPointData()->SetTCoords(tcoords);
  vtkNew<vtkCellArray> cells;
  const vtkIdType ids[4] = { 0, 1, 3, 2 };
  cells->InsertNextCell(4, ids);
  quad->SetPolys(cells);
  return quad;
}

void ImageSliceProxies::Retain(const std::set<vtkProp*>& kept)
{
  for (auto it = this->Proxies.begin(); it != this->Proxies.end();)
  {
    it = kept.count(it->first) ? std::next(it) : this->Proxies.erase(it);
  }
}

}
