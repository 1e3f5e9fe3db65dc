/**
 * The voxel-sharing links between passes (vtkVoxelGIPass::SetVoxelSource). A source owns
 * its voxels: a pass that shares another's cannot be shared, and one that is shared cannot
 * share another's, so there are no chains and hence no cycles of references.
 */
#ifndef VoxelGISourceLink_h
#define VoxelGISourceLink_h

namespace voxelgi
{

class SourceLink
{
public:
  /// Why this pass may not share the voxels of the pass whose link is `source` (`self`: that
  /// pass is this one); null when it may.
  const char* Refusal(const SourceLink* source, bool self) const;
  /// This pass shares `to`'s voxels now instead of `from`'s (null: its own).
  void Move(SourceLink* from, SourceLink* to);
  /// How many passes share this pass's voxels.
  int GetSharers() const { return this->Sharers; }

private:
  bool Shares = false;
  int Sharers = 0;
};

}

#endif
