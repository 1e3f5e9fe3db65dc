#include "Ranks.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"

#include <algorithm>
#include <chrono>
#include <limits>

namespace voxelgi
{

void Ranks::Update()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int size = controller ? controller->GetNumberOfProcesses() : 1;
  this->Controller = size > 1 ? controller : nullptr;
  this->Size = size > 1 ? size : 1;
  this->Index = size > 1 ? controller->GetLocalProcessId() : 0;
}

bool Ranks::BeginFrame(bool runs)
{
  this->Update();
  if (!this->Controller)
  {
    return runs;
  }
  this->ResetTraffic();
  return this->All(runs);
}

void Ranks::Union(double bounds[6], const std::vector<bool*>& flags)
{
  if (!this->Controller)
  {
    return;
  }
  std::vector<double> shared(6 + flags.size(), -std::numeric_limits<double>::max());
  for (int a = 0; a < 3 && *flags[0]; ++a)
  {
    shared[2 * a] = -bounds[2 * a];
    shared[2 * a + 1] = bounds[2 * a + 1];
  }
  for (std::size_t i = 0; i < flags.size(); ++i)
  {
    shared[6 + i] = *flags[i] ? 1.0 : 0.0;
  }
  this->Max(shared);
  for (int a = 0; a < 3; ++a)
  {
    bounds[2 * a] = -shared[2 * a];
    bounds[2 * a + 1] = shared[2 * a + 1];
  }
  for (std::size_t i = 0; i < flags.size(); ++i)
  {
    *flags[i] = shared[6 + i] > 0.0;
  }
}

template <typename T>
void Ranks::Reduce(T* values, std::size_t count, int operation)
{
  if (!this->Controller || count == 0)
  {
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  // MPI reductions take int counts: reduce in chunks well below 2^31 elements.
  constexpr std::size_t Chunk = std::size_t(1) << 26;
  std::vector<T> reduced(std::min(count, Chunk));
  for (std::size_t first = 0; first < count; first += Chunk)
  {
    const std::size_t n = std::min(Chunk, count - first);
    this->Controller->AllReduce(values + first, reduced.data(), static_cast<vtkIdType>(n), operation);
    std::copy(reduced.begin(), reduced.begin() + n, values + first);
  }
  this->Bytes += count * sizeof(T);
  this->Milliseconds +=
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

bool Ranks::Any(bool value)
{
  unsigned char v = value ? 1 : 0;
  this->Max(&v, 1);
  return v != 0;
}

bool Ranks::All(bool value)
{
  return !this->Any(!value);
}

void Ranks::Max(std::vector<double>& values)
{
  this->Reduce(values.data(), values.size(), vtkCommunicator::MAX_OP);
}

void Ranks::Max(unsigned char* values, std::size_t count)
{
  this->Reduce(values, count, vtkCommunicator::MAX_OP);
}

template <typename T>
void Ranks::ReduceVolume(T* voxels, int resolution, int brick, int operation)
{
  if (!this->Controller)
  {
    return;
  }
  const std::size_t n = static_cast<std::size_t>(resolution);
  const std::size_t b = static_cast<std::size_t>(brick);
  const std::size_t bricks = n / b;
  std::vector<unsigned char> occupied(bricks * bricks * bricks, 0);
  for (std::size_t z = 0; z < n; ++z)
  {
    for (std::size_t y = 0; y < n; ++y)
    {
      const T* row = voxels + n * (y + n * z);
      unsigned char* brickRow = occupied.data() + bricks * (y / b + bricks * (z / b));
      for (std::size_t x = 0; x < n; ++x)
      {
        brickRow[x / b] |= row[x] != T(0) ? 1 : 0;
      }
    }
  }
  this->Reduce(occupied.data(), occupied.size(), vtkCommunicator::MAX_OP);

  // Every rank walks the same bricks in the same order: the packed values line up.
  const auto forEachVoxel = [&](auto&& visit) {
    std::size_t index = 0;
    for (std::size_t bz = 0; bz < bricks; ++bz)
    {
      for (std::size_t by = 0; by < bricks; ++by)
      {
        for (std::size_t bx = 0; bx < bricks; ++bx, ++index)
        {
          if (!occupied[index])
          {
            continue;
          }
          for (std::size_t z = bz * b; z < (bz + 1) * b; ++z)
          {
            for (std::size_t y = by * b; y < (by + 1) * b; ++y)
            {
              T* row = voxels + n * (y + n * z);
              for (std::size_t x = bx * b; x < (bx + 1) * b; ++x)
              {
                visit(row[x]);
              }
            }
          }
        }
      }
    }
  };
  std::vector<T> packed;
  packed.reserve(static_cast<std::size_t>(std::count(occupied.begin(), occupied.end(), 1)) * b * b * b);
  forEachVoxel([&](T& v) { packed.push_back(v); });
  this->Reduce(packed.data(), packed.size(), operation);
  auto next = packed.begin();
  forEachVoxel([&](T& v) { v = *next++; });
}

void Ranks::MaxVolume(unsigned char* voxels, int resolution, int brick)
{
  this->ReduceVolume(voxels, resolution, brick, vtkCommunicator::MAX_OP);
}

void Ranks::SumVolume(unsigned int* voxels, int resolution, int brick)
{
  this->ReduceVolume(voxels, resolution, brick, vtkCommunicator::SUM_OP);
}

void Ranks::ResetTraffic()
{
  this->Bytes = 0;
  this->Milliseconds = 0.0;
}

}
