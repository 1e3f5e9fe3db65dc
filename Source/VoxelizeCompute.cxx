#include "VoxelizeCompute.h"

#include "Frame.h"
#include "VoxelGIShaders.h"
#include "shader_interface.h"

#include "vtkActor.h"
#include "vtkMatrix4x4.h"
#include "vtkProperty.h"
#include "vtk_glew.h"

#include <algorithm>

namespace voxelgi
{

namespace
{
constexpr unsigned int LocalSize = 64;   // voxelize.comp's work group
constexpr unsigned int MaxGroups = 65535; // per dimension, GL's guaranteed minimum

/// Grid coordinates from the actor's shifted model coordinates, column-major floats: composed
/// in double precision so that far-from-origin scenes stay exact.
std::array<float, 16> GridFromModel(const VoxelGrid& grid, vtkActor* actor,
  const std::array<double, 3>& shift)
{
  vtkMatrix4x4* model = actor->GetMatrix();
  const double scale = 1.0 / grid.VoxelSize;
  std::array<float, 16> m{};
  for (int row = 0; row < 3; ++row)
  {
    double translation = model->GetElement(row, 3) - grid.Origin[row];
    for (int col = 0; col < 3; ++col)
    {
      const double e = model->GetElement(row, col);
      m[4 * col + row] = static_cast<float>(scale * e);
      translation += e * shift[col];
    }
    m[12 + row] = static_cast<float>(scale * translation);
  }
  m[15] = 1.f;
  return m;
}

void Barrier()
{
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
    GL_COMMAND_BARRIER_BIT);
}
}

//------------------------------------------------------------------------------
bool VoxelizeCompute::Prepare(const std::string& defines, std::string& error)
{
  return this->Program.BuildOnce(shaders::voxelize_comp, "compute voxelization", error, defines);
}

const SceneBuffers::Entry* VoxelizeCompute::Read(vtkActor* actor)
{
  std::string why;
  return ComputeUnreadable(actor).empty() ? this->Buffers.Update(actor, why) : nullptr;
}

void VoxelizeCompute::Draw(const Frame& frame, const std::vector<Item>& items, bool staticPass)
{
  if (items.empty())
  {
    return;
  }
  // Each item's indirect arguments, then its list, as long as its triangles.
  std::vector<unsigned int> arguments;
  std::vector<unsigned int> bases;
  unsigned int words = static_cast<unsigned int>(4 * items.size());
  for (const Item& item : items)
  {
    arguments.insert(arguments.end(), { 0u, 1u, 1u, 0u });
    bases.push_back(words);
    words += item.Buffers->TriangleCount;
  }
  const std::size_t bytes = sizeof(unsigned int) * words;
  if (this->Large.Bytes() < bytes && !this->Large.Allocate(bytes))
  {
    return; // no memory for the lists: the voxels stay empty, as a failed draw would leave them
  }
  this->Large.Upload(arguments.data(), arguments.size() * sizeof(unsigned int));
  this->Large.Bind(VOXELGI_LARGE_TRIANGLE_BINDING);

  for (int pass = 0; pass < 2; ++pass)
  {
    for (std::size_t i = 0; i < items.size(); ++i)
    {
      const Item& item = items[i];
      const SceneBuffers::Entry& buffers = *item.Buffers;
      if (buffers.TriangleCount == 0)
      {
        continue;
      }
      vtkProperty* property = item.Actor->GetProperty();
      const double* diffuseColor = property->GetDiffuseColor();
      const float diffuse = static_cast<float>(property->GetDiffuse());
      const float color[4] = { diffuse * static_cast<float>(diffuseColor[0]),
        diffuse * static_cast<float>(diffuseColor[1]),
        diffuse * static_cast<float>(diffuseColor[2]),
        static_cast<float>(property->GetOpacity()) };
      const float emission[3] = { static_cast<float>(item.Emission[0]),
        static_cast<float>(item.Emission[1]), static_cast<float>(item.Emission[2]) };
      const std::array<float, 16> matrix = GridFromModel(frame.Grid, item.Actor, buffers.Shift);
      buffers.Vertices.Bind(VOXELGI_SCENE_VERTEX_BINDING);
      buffers.Indices.Bind(VOXELGI_SCENE_INDEX_BINDING);
      // Read only with per-cell colouring; something is bound in every case.
      (buffers.CellColors.IsAllocated() ? buffers.CellColors : buffers.Indices)
        .Bind(VOXELGI_SCENE_CELL_COLOR_BINDING);
      this->Program.Use(frame.Window);
      this->Program.SetMat4Array("voxelGridFromModel", 1, matrix.data());
      this->Program.SetUInt("voxelTriangleCount", buffers.TriangleCount);
      this->Program.SetInt("voxelColorMode", static_cast<int>(buffers.Colors));
      this->Program.SetVec4("voxelColor", color);
      this->Program.SetFloat("voxelDiffuse", diffuse);
      this->Program.SetVec3Array("voxelEmission", 1, emission);
      this->Program.SetInt("voxelStaticPass", staticPass ? 1 : 0);
      this->Program.SetInt("voxelLargePass", pass);
      this->Program.SetUInt("voxelLargeSlot", static_cast<unsigned int>(4 * i));
      this->Program.SetUInt("voxelLargeBase", bases[i]);
      if (pass == 0)
      {
        const unsigned int groups = (buffers.TriangleCount + LocalSize - 1) / LocalSize;
        const unsigned int x = std::min(groups, MaxGroups);
        this->Program.DispatchGroups(x, (groups + x - 1) / x, 1);
      }
      else
      {
        this->Program.DispatchIndirect(this->Large, 4 * sizeof(unsigned int) * i);
      }
    }
    Barrier(); // the lists and their counts before the second pass; the sums after it
  }
}

std::size_t VoxelizeCompute::MemoryBytes() const
{
  return this->Buffers.MemoryBytes() + this->Large.Bytes();
}

void VoxelizeCompute::ReleaseGraphicsResources()
{
  this->Program.Release();
  this->Buffers.ReleaseGraphicsResources();
  this->Large.Release();
}

}
