#include "VolumeVoxels.h"

#include "Frame.h"
#include "VoxelGIShaders.h"
#include "shader_interface.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPiecewiseFunction.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"
#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace voxelgi
{

namespace
{
constexpr int TransferSize = 256; // entries of the transfer-function table

vtkImageData* Input(vtkVolume* volume, vtkDataArray** scalars, int* cellFlag)
{
  vtkAbstractVolumeMapper* mapper = volume->GetMapper();
  auto* image = mapper ? vtkImageData::SafeDownCast(mapper->GetDataSetInput()) : nullptr;
  if (image)
  {
    *scalars = vtkAbstractMapper::GetScalars(image, mapper->GetScalarMode(),
      mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), *cellFlag);
  }
  return image;
}

/// The volume's scalars as floats, in the image's point order.
std::vector<float> Floats(vtkDataArray* scalars)
{
  std::vector<float> values(static_cast<std::size_t>(scalars->GetNumberOfTuples()));
  switch (scalars->GetDataType())
  {
    vtkTemplateMacro(std::transform(static_cast<const VTK_TT*>(scalars->GetVoidPointer(0)),
      static_cast<const VTK_TT*>(scalars->GetVoidPointer(0)) + values.size(), values.begin(),
      [](VTK_TT v) { return static_cast<float>(v); }));
    default:
      for (std::size_t i = 0; i < values.size(); ++i)
      {
        values[i] = static_cast<float>(scalars->GetTuple1(static_cast<vtkIdType>(i)));
      }
  }
  return values;
}

/// Continuous texel coordinates of the volume's scalars (point i at i) from grid
/// coordinates, column-major floats, composed in double precision.
std::array<float, 16> IndexFromGrid(const VoxelGrid& grid, vtkVolume* volume, vtkImageData* image)
{
  vtkNew<vtkMatrix4x4> worldFromGrid;
  for (int i = 0; i < 3; ++i)
  {
    worldFromGrid->SetElement(i, i, grid.VoxelSize);
    worldFromGrid->SetElement(i, 3, grid.Origin[i]);
  }
  vtkNew<vtkMatrix4x4> physicalFromIndex;
  physicalFromIndex->DeepCopy(image->GetIndexToPhysicalMatrix());
  // The texture's first texel is the extent's first point.
  const int* extent = image->GetExtent();
  vtkNew<vtkMatrix4x4> shift;
  for (int i = 0; i < 3; ++i)
  {
    shift->SetElement(i, 3, extent[2 * i]);
  }
  vtkMatrix4x4::Multiply4x4(physicalFromIndex, shift, physicalFromIndex);
  vtkNew<vtkMatrix4x4> worldFromIndex;
  vtkMatrix4x4::Multiply4x4(volume->GetMatrix(), physicalFromIndex, worldFromIndex);
  worldFromIndex->Invert();
  vtkNew<vtkMatrix4x4> indexFromGrid;
  vtkMatrix4x4::Multiply4x4(worldFromIndex, worldFromGrid, indexFromGrid);
  std::array<float, 16> m{};
  for (int row = 0; row < 4; ++row)
  {
    for (int col = 0; col < 4; ++col)
    {
      m[4 * col + row] = static_cast<float>(indexFromGrid->GetElement(row, col));
    }
  }
  return m;
}

bool SameGrid(const VoxelGrid& a, const VoxelGrid& b)
{
  return a.Origin == b.Origin && a.VoxelSize == b.VoxelSize && a.Resolution == b.Resolution;
}
}

struct VolumeVoxels::Source
{
  vtkWeakPointer<vtkVolume> Volume;
  vtkSmartPointer<vtkTextureObject> Scalars;
  vtkSmartPointer<vtkTextureObject> Transfer;
  vtkMTimeType ScalarsTime = 0;
  vtkMTimeType TransferTime = 0;
  float Range[2] = { 0.f, 1.f }; // scalars at the table's first and last entry
};

VolumeVoxels::VolumeVoxels() = default;
VolumeVoxels::~VolumeVoxels() = default;

//------------------------------------------------------------------------------
std::string VolumeVoxels::LeftOutReason(vtkVolume* volume)
{
  vtkDataArray* scalars = nullptr;
  int cellFlag = 0;
  vtkImageData* image = Input(volume, &scalars, &cellFlag);
  if (!image)
  {
    return "its input is not image data";
  }
  auto* mapper = vtkVolumeMapper::SafeDownCast(volume->GetMapper());
  if (mapper && mapper->GetBlendMode() != vtkVolumeMapper::COMPOSITE_BLEND)
  {
    return "a blend mode other than composite";
  }
  if (!scalars || cellFlag != 0)
  {
    return "no point scalars";
  }
  if (scalars->GetNumberOfComponents() != 1)
  {
    return "several scalar components";
  }
  const int* dims = image->GetDimensions();
  if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
  {
    return "fewer than two points on an axis";
  }
  return std::string();
}

//------------------------------------------------------------------------------
bool VolumeVoxels::Prepare(const Frame& frame, std::string& error)
{
  if (!frame.Plan.Voxels.Volumes)
  {
    this->ReleaseGraphicsResources(frame.Window);
    return true;
  }
  const int resolution = frame.Plan.Voxels.Grid.Resolution;
  if (this->Grid.Resolution() != resolution)
  {
    this->Built.clear();
  }
  if (!this->Grid.Allocate(GL_RGBA8, resolution))
  {
    error = "could not allocate the volumes' voxels";
    return false;
  }
  return this->Program.BuildOnce(shaders::voxelize_volume_comp, "volume resampling", error);
}

void VolumeVoxels::Run(const Frame& frame)
{
  if (!this->Grid.IsAllocated() ||
    (*frame.Volumes == this->Built && SameGrid(frame.Grid, this->BuiltGrid)))
  {
    return; // nothing changed: the grid holds these volumes
  }
  ScopedStage stage(*frame.Clock, stage::Volumes);
  bool first = true;
  for (const VolumeRecord& record : *frame.Volumes)
  {
    if (record.Volume)
    {
      Source& source = this->Upload(frame, record.Volume);
      this->Resample(frame, record.Volume, source, first);
      first = false;
    }
  }
  if (first)
  {
    this->Grid.Clear(); // every volume went away since the scan
  }
  // Volumes that left the scene give their textures back.
  this->Sources.erase(std::remove_if(this->Sources.begin(), this->Sources.end(),
                        [&](const Source& s) {
                          return std::none_of(frame.Volumes->begin(), frame.Volumes->end(),
                            [&](const VolumeRecord& r) { return r.Volume == s.Volume; });
                        }),
    this->Sources.end());
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  this->Built = *frame.Volumes;
  this->BuiltGrid = frame.Grid;
}

VolumeVoxels::Source& VolumeVoxels::Upload(const Frame& frame, vtkVolume* volume)
{
  auto found = std::find_if(this->Sources.begin(), this->Sources.end(),
    [volume](const Source& s) { return s.Volume == volume; });
  if (found == this->Sources.end())
  {
    this->Sources.emplace_back();
    found = this->Sources.end() - 1;
    found->Volume = volume;
  }
  Source& source = *found;
  vtkDataArray* scalars = nullptr;
  int cellFlag = 0;
  vtkImageData* image = Input(volume, &scalars, &cellFlag);
  const vtkMTimeType scalarsTime = std::max(image->GetMTime(), scalars->GetMTime());
  if (!source.Scalars || scalarsTime != source.ScalarsTime)
  {
    const int* dims = image->GetDimensions();
    std::vector<float> values = Floats(scalars);
    source.Scalars = vtkSmartPointer<vtkTextureObject>::New();
    source.Scalars->SetContext(frame.Window);
    source.Scalars->Create3DFromRaw(static_cast<unsigned int>(dims[0]),
      static_cast<unsigned int>(dims[1]), static_cast<unsigned int>(dims[2]), 1, VTK_FLOAT,
      values.data());
    source.Scalars->SetMinificationFilter(vtkTextureObject::Linear);
    source.Scalars->SetMagnificationFilter(vtkTextureObject::Linear);
    source.Scalars->SetWrapS(vtkTextureObject::ClampToEdge);
    source.Scalars->SetWrapT(vtkTextureObject::ClampToEdge);
    source.Scalars->SetWrapR(vtkTextureObject::ClampToEdge);
    source.ScalarsTime = scalarsTime;
  }
  vtkVolumeProperty* property = volume->GetProperty();
  if (!source.Transfer || property->GetMTime() != source.TransferTime)
  {
    vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
    const bool rgb = property->GetColorChannels(0) == 3;
    vtkColorTransferFunction* color = rgb ? property->GetRGBTransferFunction(0) : nullptr;
    vtkPiecewiseFunction* gray = rgb ? nullptr : property->GetGrayTransferFunction(0);
    double range[2];
    opacity->GetRange(range);
    const double* colorRange = rgb ? color->GetRange() : gray->GetRange();
    range[0] = std::min(range[0], colorRange[0]);
    range[1] = std::max(range[1], colorRange[1]);
    std::vector<float> table(4 * TransferSize);
    for (int i = 0; i < TransferSize; ++i)
    {
      const double s = range[0] + (range[1] - range[0]) * i / (TransferSize - 1);
      double c[3];
      if (rgb)
      {
        color->GetColor(s, c);
      }
      else
      {
        c[0] = c[1] = c[2] = gray->GetValue(s);
      }
      for (int k = 0; k < 3; ++k)
      {
        table[4 * i + k] = static_cast<float>(std::min(std::max(c[k], 0.0), 1.0));
      }
      table[4 * i + 3] = static_cast<float>(std::min(std::max(opacity->GetValue(s), 0.0), 1.0));
    }
    source.Transfer = vtkSmartPointer<vtkTextureObject>::New();
    source.Transfer->SetContext(frame.Window);
    source.Transfer->Create2DFromRaw(TransferSize, 1, 4, VTK_FLOAT, table.data());
    source.Transfer->SetMinificationFilter(vtkTextureObject::Linear);
    source.Transfer->SetMagnificationFilter(vtkTextureObject::Linear);
    source.Transfer->SetWrapS(vtkTextureObject::ClampToEdge);
    source.Transfer->SetWrapT(vtkTextureObject::ClampToEdge);
    source.Range[0] = static_cast<float>(range[0]);
    source.Range[1] = static_cast<float>(range[1]);
    source.TransferTime = property->GetMTime();
  }
  return source;
}

void VolumeVoxels::Resample(const Frame& frame, vtkVolume* volume, Source& source, bool first)
{
  vtkDataArray* scalars = nullptr;
  int cellFlag = 0;
  vtkImageData* image = Input(volume, &scalars, &cellFlag);
  const std::array<float, 16> matrix = IndexFromGrid(frame.Grid, volume, image);
  const int* dims = image->GetDimensions();
  const float dimensions[3] = { static_cast<float>(dims[0]), static_cast<float>(dims[1]),
    static_cast<float>(dims[2]) };
  // The first volume writes every voxel (zero outside it); the others their bounds.
  const int res = frame.Grid.Resolution;
  int lo[3] = { 0, 0, 0 };
  int count[3] = { res, res, res };
  if (!first)
  {
    const double* b = volume->GetBounds();
    for (int i = 0; i < 3; ++i)
    {
      const double a = (b[2 * i] - frame.Grid.Origin[i]) / frame.Grid.VoxelSize;
      const double z = (b[2 * i + 1] - frame.Grid.Origin[i]) / frame.Grid.VoxelSize;
      lo[i] = std::max(0, static_cast<int>(std::floor(a)));
      count[i] = std::min(res, static_cast<int>(std::ceil(z)) + 1) - lo[i];
    }
    if (count[0] <= 0 || count[1] <= 0 || count[2] <= 0)
    {
      return;
    }
  }
  const float first3[3] = { static_cast<float>(lo[0]), static_cast<float>(lo[1]),
    static_cast<float>(lo[2]) };
  const double unit = volume->GetProperty()->GetScalarOpacityUnitDistance(0);
  ScopedTextures textures({ source.Scalars, source.Transfer });
  if (!textures.Complete())
  {
    return;
  }
  this->Grid.BindImage(0, first ? GL_WRITE_ONLY : GL_READ_WRITE);
  this->Program.Use(frame.Window);
  this->Program.SetInt("volumeScalars", source.Scalars->GetTextureUnit());
  this->Program.SetInt("volumeTransfer", source.Transfer->GetTextureUnit());
  this->Program.SetMat4Array("volumeIndexFromGrid", 1, matrix.data());
  this->Program.SetVec3Array("volumeDimensions", 1, dimensions);
  this->Program.SetVec3Array("volumeFirst", 1, first3);
  this->Program.SetVec2("volumeRange", source.Range[0], source.Range[1]);
  this->Program.SetFloat("volumeUnitVoxels",
    static_cast<float>(std::max(unit, 1e-12) / frame.Grid.VoxelSize));
  this->Program.SetInt("volumeOverwrite", first ? 1 : 0);
  auto groups = [](int n) { return static_cast<unsigned int>((n + VOXELGI_LOCAL_SIZE - 1) / VOXELGI_LOCAL_SIZE); };
  this->Program.DispatchGroups(groups(count[0]), groups(count[1]), groups(count[2]));
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

std::size_t VolumeVoxels::MemoryBytes() const
{
  std::size_t bytes = this->Grid.Bytes();
  for (const Source& source : this->Sources)
  {
    if (source.Scalars)
    {
      bytes += std::size_t(source.Scalars->GetWidth()) * source.Scalars->GetHeight() *
        source.Scalars->GetDepth() * sizeof(float);
    }
    bytes += source.Transfer ? 4 * TransferSize * sizeof(float) : 0;
  }
  return bytes;
}

void VolumeVoxels::ReleaseGraphicsResources(vtkWindow* window)
{
  for (Source& source : this->Sources)
  {
    if (source.Scalars)
    {
      source.Scalars->ReleaseGraphicsResources(window);
    }
    if (source.Transfer)
    {
      source.Transfer->ReleaseGraphicsResources(window);
    }
  }
  this->Sources.clear();
  this->Grid.Release();
  this->Program.Release();
  this->Built.clear();
}

}
