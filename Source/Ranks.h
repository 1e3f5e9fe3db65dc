/**
 * Ranks: the processes of a distributed render (ParaView's pvbatch or pvserver under MPI),
 * through VTK's global vtkMultiProcessController. Each rank holds a piece of the data; the
 * pass merges their voxels so that every rank lights and traces the same grid. Every call is
 * collective: all ranks must make the same calls in the same order, so the pass reduces each
 * decision that could differ between ranks before acting on it. With one process (no
 * controller, or a controller of one process) nothing is communicated.
 */
#ifndef VoxelGIRanks_h
#define VoxelGIRanks_h

#include <cstddef>
#include <vector>

class vtkMultiProcessController;

namespace voxelgi
{

class Ranks
{
public:
  /// Follow the global controller (ParaView sets it before the first render).
  void Update();
  bool Distributed() const { return this->Controller != nullptr; }
  int Rank() const { return this->Index; }
  int Count() const { return this->Size; }

  /// Logical OR / AND of `value` over the ranks.
  bool Any(bool value);
  bool All(bool value);
  /// Elementwise maximum over the ranks, in place.
  void Max(std::vector<double>& values);
  void Max(unsigned char* values, std::size_t count);

  /// Elementwise maximum / sum over the ranks of a voxel volume (`resolution`^3 values, x
  /// fastest; `brick` divides `resolution`), in place. Only the bricks (`brick`^3 voxels) in
  /// which some rank holds a nonzero value travel: the ranks first agree on those, one byte a
  /// brick. Surfaces occupy a small share of a grid's bricks, so this sends a fraction of the
  /// volume; the result equals the dense reduction, since zero is the identity of both.
  void MaxVolume(unsigned char* voxels, int resolution, int brick);
  void SumVolume(unsigned int* voxels, int resolution, int brick);

  /// Bytes this rank contributed to reductions, and the time they took, since the last
  /// ResetTraffic().
  void ResetTraffic();
  std::size_t GetBytes() const { return this->Bytes; }
  double GetMilliseconds() const { return this->Milliseconds; }

private:
  template <typename T>
  void Reduce(T* values, std::size_t count, int operation);
  template <typename T>
  void ReduceVolume(T* voxels, int resolution, int brick, int operation);

  vtkMultiProcessController* Controller = nullptr;
  int Index = 0;
  int Size = 1;
  std::size_t Bytes = 0;
  double Milliseconds = 0.0;
};

}

#endif
