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
#include <utility>
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

  /// The start of a frame's shared part: follow the controller, reset the traffic counts,
  /// and whether every rank `runs` GI (each voxelizes its piece into one grid: all, or none).
  bool BeginFrame(bool runs);
  /// The shared part ran ahead of the frame's Render() (vtkVoxelGIPass::RenderRanks): its
  /// verdict is held until Render() takes it.
  void Hold(bool active)
  {
    this->Held = true;
    this->HeldActive = active;
  }
  bool Take(bool& active)
  {
    active = this->HeldActive;
    return std::exchange(this->Held, false);
  }

  /// One grid around every rank's piece: the union of the `bounds` of the ranks whose
  /// `*flags[0]` (they collected a piece) holds, and the OR of every flag (one reduction).
  void Union(double bounds[6], const std::vector<bool*>& flags);

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
  bool Held = false;
  bool HeldActive = false;
};

}

#endif
