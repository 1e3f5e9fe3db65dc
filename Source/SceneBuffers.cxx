#include "SceneBuffers.h"

#include "SceneScan.h"

#include "vtkActor.h"
#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkDataArrayRange.h"
#include "vtkFollower.h"
#include "vtkMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <iterator>
#include <unordered_set>

namespace voxelgi
{

namespace
{
std::uint32_t PackColor(const unsigned char* rgba)
{
  return static_cast<std::uint32_t>(rgba[0]) | (static_cast<std::uint32_t>(rgba[1]) << 8) |
    (static_cast<std::uint32_t>(rgba[2]) << 16) | (static_cast<std::uint32_t>(rgba[3]) << 24);
}

/// Marks a triangle with an index beyond the points, removed after the parallel write.
constexpr std::uint32_t Damaged = 0xFFFFFFFFu;

/// Writes the vertices: positions relative to the shift, colours per point (null: none). Typed
/// for the points' own array, since a virtual call per coordinate costs more than the copy.
struct VertexWriter
{
  template <typename Array>
  void operator()(Array* array, const std::array<double, 3>& shift, const unsigned char* colors,
    TriangleArrays::Vertex* out) const
  {
    const auto tuples = vtk::DataArrayTupleRange<3>(array);
    vtkSMPTools::For(0, tuples.size(), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const auto p = tuples[i];
        TriangleArrays::Vertex& v = out[i];
        for (int a = 0; a < 3; ++a)
        {
          v.Position[a] = static_cast<float>(static_cast<double>(p[a]) - shift[a]);
        }
        v.Color = colors ? PackColor(colors + 4 * i) : 0u;
      }
    });
  }
};

/// Cells are read in blocks: each counts its triangles, then writes them where the blocks
/// before it end.
constexpr vtkIdType BlockCells = 1 << 14;

/// Where each block's triangles start (one more entry: the total). A cell of n points gives
/// n - 2 triangles.
template <typename Offset>
std::vector<std::size_t> BlockStarts(const Offset* offsets, vtkIdType cells)
{
  const vtkIdType blocks = (cells + BlockCells - 1) / BlockCells;
  std::vector<std::size_t> first(static_cast<std::size_t>(blocks) + 1, 0);
  vtkSMPTools::For(0, blocks, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType block = begin; block < end; ++block)
    {
      std::size_t count = 0;
      for (vtkIdType c = block * BlockCells; c < std::min(cells, (block + 1) * BlockCells); ++c)
      {
        const vtkIdType n = static_cast<vtkIdType>(offsets[c + 1] - offsets[c]);
        count += static_cast<std::size_t>(n > 2 ? n - 2 : 0);
      }
      first[block + 1] = count;
    }
  });
  for (vtkIdType block = 0; block < blocks; ++block)
  {
    first[block + 1] += first[block];
  }
  return first;
}

/// Writes the n - 2 triangles of a cell of n points at `t` (three indices each) as VTK's index
/// buffers order them: polygons as fans from their first point, strips with every other
/// triangle turned so that all face one way. False when a triangle has an index beyond the
/// points (marked Damaged).
template <typename Id>
bool WriteCell(const Id* cell, vtkIdType n, bool strips, vtkIdType points, std::uint32_t* t)
{
  bool whole = true;
  for (vtkIdType k = 2; k < n; ++k, t += 3)
  {
    const vtkIdType i = k - 2;
    const vtkIdType a = strips ? cell[i] : cell[0];
    const vtkIdType b = strips ? cell[i + 1 + i % 2] : cell[k - 1];
    const vtkIdType d = strips ? cell[i + 1 + (i + 1) % 2] : cell[k];
    if (a < 0 || b < 0 || d < 0 || a >= points || b >= points || d >= points)
    {
      t[0] = Damaged; // never an index beyond the buffer
      whole = false;
      continue;
    }
    t[0] = static_cast<std::uint32_t>(a);
    t[1] = static_cast<std::uint32_t>(b);
    t[2] = static_cast<std::uint32_t>(d);
  }
  return whole;
}

/// Removes the triangles marked Damaged from triangle `base` on (and their cell colours, where
/// there are), keeping the order of the rest.
void RemoveDamaged(TriangleArrays& arrays, std::size_t base)
{
  std::vector<std::uint32_t>& indices = arrays.Indices;
  std::vector<std::uint32_t>& colors = arrays.CellColors;
  std::size_t kept = base;
  for (std::size_t t = base; 3 * t < indices.size(); ++t)
  {
    if (indices[3 * t] != Damaged)
    {
      std::copy_n(indices.begin() + 3 * t, 3, indices.begin() + 3 * kept);
      if (!colors.empty())
      {
        colors[kept] = colors[t];
      }
      ++kept;
    }
  }
  indices.resize(3 * kept);
  colors.resize(colors.empty() ? 0 : kept);
}

/// Appends the triangles of a cell array (cell ids from `firstCell`), read straight from its
/// offsets and connectivity, in parallel.
struct TriangleWriter
{
  template <typename State>
  void operator()(State& state, bool strips, vtkIdType firstCell, vtkIdType points,
    const unsigned char* cellColors, TriangleArrays& arrays) const
  {
    const vtkIdType cells = state.GetNumberOfCells();
    const auto* offsets = state.GetOffsets()->GetPointer(0);
    const auto* ids = state.GetConnectivity()->GetPointer(0);
    const std::vector<std::size_t> first = BlockStarts(offsets, cells);
    const std::size_t base = arrays.Indices.size() / 3;
    arrays.Indices.resize(3 * (base + first.back()));
    if (cellColors)
    {
      arrays.CellColors.resize(base + first.back());
    }
    std::uint32_t* out = arrays.Indices.data() + 3 * base;
    std::uint32_t* outColors = cellColors ? arrays.CellColors.data() + base : nullptr;
    std::atomic<bool> damaged{ false };
    const vtkIdType blocks = static_cast<vtkIdType>(first.size()) - 1;
    vtkSMPTools::For(0, blocks, [&](vtkIdType begin, vtkIdType end) {
      bool whole = true;
      for (vtkIdType block = begin; block < end; ++block)
      {
        std::size_t t = first[block];
        for (vtkIdType c = block * BlockCells; c < std::min(cells, (block + 1) * BlockCells); ++c)
        {
          const vtkIdType n = static_cast<vtkIdType>(offsets[c + 1] - offsets[c]);
          whole = WriteCell(ids + offsets[c], n, strips, points, out + 3 * t) && whole;
          const std::size_t made = static_cast<std::size_t>(std::max<vtkIdType>(n - 2, 0));
          if (outColors)
          {
            std::fill_n(outColors + t, made, PackColor(cellColors + 4 * (firstCell + c)));
          }
          t += made;
        }
      }
      if (!whole)
      {
        damaged = true;
      }
    });
    if (damaged)
    {
      RemoveDamaged(arrays, base);
    }
  }
};
}

//------------------------------------------------------------------------------
std::string ComputeUnreadable(vtkActor* actor)
{
  vtkMapper* mapper = actor->GetMapper();
  // The exact classes: a subclass (a user's own mapper, glyphs, composite data) or an actor
  // that draws through an internal one (LOD actors, followers turning with a camera) draws
  // something else. A follower without a camera (every vedo mesh) draws as an actor.
  auto* follower = vtkFollower::SafeDownCast(actor);
  const bool plainFollower = follower && !follower->GetCamera() &&
    (std::strcmp(actor->GetClassName(), "vtkFollower") == 0 ||
      std::strcmp(actor->GetClassName(), "vtkOpenGLFollower") == 0);
  if (std::strcmp(actor->GetClassName(), "vtkOpenGLActor") != 0 && !plainFollower)
  {
    return std::string("actor class ") + actor->GetClassName() +
      (follower ? " (turning with a camera)" : "");
  }
  if (!mapper || std::strcmp(mapper->GetClassName(), "vtkOpenGLPolyDataMapper") != 0)
  {
    return std::string("mapper class ") + (mapper ? mapper->GetClassName() : "none");
  }
  vtkProperty* property = actor->GetProperty();
  if (actor->GetTexture() || property->GetNumberOfTextures() > 0)
  {
    return "textures";
  }
  if (actor->GetBackfaceProperty())
  {
    return "a backface property";
  }
  if (mapper->GetNumberOfClippingPlanes() > 0)
  {
    return "clipping planes";
  }
  if (mapper->GetScalarVisibility() && mapper->GetInterpolateScalarsBeforeMapping())
  {
    return "scalars interpolated before mapping";
  }
  return std::string();
}

bool ReadTriangles(vtkActor* actor, vtkPolyData* input, TriangleArrays& arrays, std::string& why)
{
  vtkMapper* mapper = actor->GetMapper();
  // Emptied, not freed: the memory of the last read is reused (fresh pages cost more than
  // the copy).
  arrays.Vertices.clear();
  arrays.Indices.clear();
  arrays.CellColors.clear();
  arrays.Shift = { { 0.0, 0.0, 0.0 } };
  arrays.Colors = TriangleColors::Actor;
  vtkPoints* points = input->GetPoints();
  const vtkIdType count = points ? points->GetNumberOfPoints() : 0;
  if (count == 0)
  {
    return true;
  }
  int cellFlag = 0;
  vtkUnsignedCharArray* colors =
    mapper->MapScalars(input, actor->GetProperty()->GetOpacity(), cellFlag);
  if (colors && cellFlag == 2)
  {
    why = "colours from field data";
    return false;
  }
  arrays.Colors = !colors ? TriangleColors::Actor
                          : (cellFlag == 1 ? TriangleColors::Cell : TriangleColors::Vertex);
  const double* bounds = input->GetBounds();
  for (int a = 0; a < 3; ++a)
  {
    const double center = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
    arrays.Shift[a] = std::isfinite(center) ? center : 0.0;
  }
  arrays.Vertices.resize(static_cast<std::size_t>(count));
  const unsigned char* pointColors =
    arrays.Colors == TriangleColors::Vertex ? colors->GetPointer(0) : nullptr;
  VertexWriter writeVertices;
  if (!vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Reals>::Execute(points->GetData(),
        writeVertices, arrays.Shift, pointColors, arrays.Vertices.data()))
  {
    writeVertices(points->GetData(), arrays.Shift, pointColors, arrays.Vertices.data());
  }
  const unsigned char* cellColors =
    arrays.Colors == TriangleColors::Cell ? colors->GetPointer(0) : nullptr;
  // Cell ids run over vertices, lines, polygons, strips in that order (VTK's cell data).
  const vtkIdType polys = input->GetNumberOfVerts() + input->GetNumberOfLines();
  input->GetPolys()->Visit(TriangleWriter{}, false, polys, count, cellColors, arrays);
  input->GetStrips()->Visit(
    TriangleWriter{}, true, polys + input->GetNumberOfPolys(), count, cellColors, arrays);
  return true;
}

//------------------------------------------------------------------------------
const SceneBuffers::Entry* SceneBuffers::Update(vtkActor* actor, std::string& why)
{
  vtkMapper* mapper = actor->GetMapper();
  auto* input = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
  if (!input)
  {
    why = "no polydata input";
    return nullptr;
  }
  Entry& entry = this->Entries[actor];
  const double opacity = actor->GetProperty()->GetOpacity();
  if (entry.Actor == actor && entry.Input == input && entry.InputTime == input->GetMTime() &&
    entry.MapperTime == mapper->GetMTime() &&
    (entry.Opacity == opacity || entry.Colors == TriangleColors::Actor))
  {
    return &entry;
  }
  TriangleArrays& arrays = this->Scratch;
  if (!ReadTriangles(actor, input, arrays, why))
  {
    this->Erase(this->Entries.find(actor));
    return nullptr;
  }
  entry.Actor = actor;
  entry.Input = input;
  entry.InputTime = input->GetMTime();
  entry.MapperTime = mapper->GetMTime(); // after MapScalars, which may build a lookup table
  entry.Opacity = opacity;
  entry.Shift = arrays.Shift;
  entry.Colors = arrays.Colors;
  entry.TriangleCount = static_cast<unsigned int>(arrays.Indices.size() / 3);
  entry.CellColors.Release();
  if (entry.TriangleCount == 0)
  {
    entry.Vertices.Release();
    entry.Indices.Release();
    return &entry;
  }
  const std::size_t vertexBytes = arrays.Vertices.size() * sizeof(TriangleArrays::Vertex);
  const std::size_t indexBytes = arrays.Indices.size() * sizeof(std::uint32_t);
  const std::size_t colorBytes = arrays.CellColors.size() * sizeof(std::uint32_t);
  if (!entry.Vertices.Allocate(vertexBytes) || !entry.Indices.Allocate(indexBytes) ||
    (colorBytes > 0 && !entry.CellColors.Allocate(colorBytes)))
  {
    why = "no GPU memory for its triangles";
    this->Erase(this->Entries.find(actor));
    return nullptr;
  }
  entry.Vertices.Upload(arrays.Vertices.data(), vertexBytes);
  entry.Indices.Upload(arrays.Indices.data(), indexBytes);
  if (colorBytes > 0)
  {
    entry.CellColors.Upload(arrays.CellColors.data(), colorBytes);
  }
  return &entry;
}

void SceneBuffers::Retain(const std::vector<ActorRecord>& records)
{
  std::unordered_set<vtkActor*> kept;
  for (const ActorRecord& record : records)
  {
    kept.insert(record.Actor);
  }
  for (auto it = this->Entries.begin(); it != this->Entries.end();)
  {
    it = (!it->second.Actor || !kept.count(it->first)) ? this->Erase(it) : std::next(it);
  }
}

std::size_t SceneBuffers::MemoryBytes() const
{
  std::size_t bytes = 0;
  for (const auto& entry : this->Entries)
  {
    bytes += entry.second.Vertices.Bytes() + entry.second.Indices.Bytes() +
      entry.second.CellColors.Bytes();
  }
  return bytes;
}

SceneBuffers::Map::iterator SceneBuffers::Erase(Map::iterator it)
{
  it->second.Vertices.Release();
  it->second.Indices.Release();
  it->second.CellColors.Release();
  return this->Entries.erase(it);
}

void SceneBuffers::ReleaseGraphicsResources()
{
  for (auto it = this->Entries.begin(); it != this->Entries.end();)
  {
    it = this->Erase(it);
  }
}

}
