#include "Ranks.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"

#include <algorithm>
#include <chrono>

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

void Ranks::Sum(unsigned int* values, std::size_t count)
{
  this->Reduce(values, count, vtkCommunicator::SUM_OP);
}

void Ranks::ResetTraffic()
{
  this->Bytes = 0;
  this->Milliseconds = 0.0;
}

}
