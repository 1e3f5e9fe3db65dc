#include "SourceLink.h"

namespace voxelgi
{

const char* SourceLink::Refusal(const SourceLink* source, bool self) const
{
  if (!source)
  {
    return nullptr;
  }
  if (self)
  {
    return "a pass cannot share its own voxels";
  }
  if (source->Shares)
  {
    return "that pass shares another pass's voxels itself";
  }
  return this->Sharers > 0 ? "other passes share this pass's voxels" : nullptr;
}

void SourceLink::Move(SourceLink* from, SourceLink* to)
{
  if (from)
  {
    --from->Sharers;
  }
  if (to)
  {
    ++to->Sharers;
  }
  this->Shares = to != nullptr;
}

}
