#include "VolumeReadback.h"

#include "Composite.h"
#include "GLHelpers.h"
#include "LightVoxels.h"
#include "VoxelView.h"
#include "VoxelizePass.h"
#include "vtkVoxelGIPass.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkTypeUInt32Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

#include <algorithm>
#include <vector>

namespace voxelgi
{

namespace
{
vtkSmartPointer<vtkDataArray> ReadTexels(const Volume3D& volume, bool floats, vtkIdType n)
{
  if (floats)
  {
    auto values = vtkSmartPointer<vtkFloatArray>::New();
    values->SetNumberOfComponents(4);
    values->SetNumberOfTuples(n);
    volume.Read(GL_RGBA, GL_FLOAT, values->GetPointer(0));
    return values;
  }
  auto bytes = vtkSmartPointer<vtkUnsignedCharArray>::New();
  bytes->SetNumberOfComponents(4);
  bytes->SetNumberOfTuples(n);
  volume.Read(GL_RGBA, GL_UNSIGNED_BYTE, bytes->GetPointer(0));
  return bytes;
}
}

bool ReadVolume(const VoxelView& view, int volume, vtkImageData* image)
{
  const VoxelizePass& voxels = *view.Voxelization;
  const Volume3D& radiance = view.Lighting->GetRadiance();
  const VoxelGrid& grid = view.Grid;
  const int res = voxels.GetResolution();
  if (!image || !view.Window || res <= 0 ||
    (volume == vtkVoxelGIPass::VOLUME_EMISSION && !voxels.HasEmission()) ||
    (volume == vtkVoxelGIPass::VOLUME_RADIANCE && !radiance.IsAllocated()))
  {
    return false;
  }
  if (!MakeCurrentForReading(view.Window))
  {
    return false;
  }
  const vtkIdType n = static_cast<vtkIdType>(res) * res * res;
  vtkSmartPointer<vtkDataArray> array;
  switch (volume)
  {
    case vtkVoxelGIPass::VOLUME_ALBEDO:
      array = ReadTexels(voxels.GetAlbedo(), false, n);
      break;
    case vtkVoxelGIPass::VOLUME_NORMAL:
      array = ReadTexels(voxels.GetNormal(), false, n);
      break;
    case vtkVoxelGIPass::VOLUME_EMISSION:
      array = ReadTexels(voxels.GetEmission(), true, n);
      break;
    case vtkVoxelGIPass::VOLUME_RADIANCE:
      array = ReadTexels(radiance, true, n);
      break;
    case vtkVoxelGIPass::VOLUME_COUNT:
    {
      std::vector<unsigned int> counts;
      voxels.ReadCounts(counts);
      auto uints = vtkSmartPointer<vtkTypeUInt32Array>::New();
      uints->SetNumberOfTuples(n);
      std::copy(counts.begin(), counts.end(), uints->GetPointer(0));
      array = uints;
      break;
    }
    case vtkVoxelGIPass::VOLUME_FLAG:
    {
      std::vector<unsigned char> flags;
      voxels.ReadFlags(flags);
      auto bytes = vtkSmartPointer<vtkUnsignedCharArray>::New();
      bytes->SetNumberOfTuples(n);
      std::copy(flags.begin(), flags.end(), bytes->GetPointer(0));
      array = bytes;
      break;
    }
    default:
      return false;
  }
  image->Initialize();
  image->SetDimensions(res, res, res);
  image->SetSpacing(grid.VoxelSize, grid.VoxelSize, grid.VoxelSize);
  const double h = 0.5 * grid.VoxelSize;
  image->SetOrigin(grid.Origin.x + h, grid.Origin.y + h, grid.Origin.z + h);
  array->SetName("Voxels");
  image->GetPointData()->SetScalars(array);
  return true;
}

bool ReadImage(Composite& composite, vtkOpenGLRenderWindow* window, int image, vtkFloatArray* pixels)
{
  std::vector<float> rgba;
  int w = 0, h = 0;
  if (!pixels || !window || !composite.Read(window, image, rgba, w, h))
  {
    return false;
  }
  pixels->SetNumberOfComponents(4);
  pixels->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  std::copy(rgba.begin(), rgba.end(), pixels->GetPointer(0));
  return true;
}

}
