#include "Frame.h"

#include "SoftwareProfile.h"

namespace voxelgi
{

Settings Snapshot(vtkVoxelGIPassSettings* pass, bool hasConservativeRaster, bool softwareProfile)
{
  Settings c = SnapshotSettings(pass);
  c.HardwareConservativeRaster = c.HardwareConservativeRaster && hasConservativeRaster;
  if (softwareProfile)
  {
    ApplySoftwareProfile(c);
  }
  return c;
}

bool StageClock::Ran(int stage) const
{
  return stage >= 0 && stage < stage::Count && this->DidRun[stage];
}

double StageClock::Milliseconds(int stage) const
{
  return (stage >= 0 && stage < stage::Count) ? this->Times[stage] : 0.0;
}

void StageClock::Print(ostream& os, vtkIndent indent) const
{
  for (int s = 0; s < stage::Count; ++s)
  {
    os << indent << "Stage " << stage::Name(s) << ": " << (this->DidRun[s] ? "ran" : "skipped");
    if (this->DidRun[s] && this->Timing)
    {
      os << ", " << this->Times[s] << " ms";
    }
    os << "\n";
  }
}

void StageClock::Reset()
{
  this->DidRun.fill(false);
  this->Times.fill(0.0);
}

void StageClock::Begin(int stage)
{
  // A stage that runs in several parts (the trace and its composite) is timed from the
  // start of its first part to the end of its last.
  if (this->Timing && !this->DidRun[stage])
  {
    this->Timers[stage].Begin();
  }
  this->DidRun[stage] = true;
}

void StageClock::End(int stage)
{
  if (this->Timing)
  {
    this->Timers[stage].End();
  }
}

void StageClock::SetCpuTime(int stage, double milliseconds)
{
  this->DidRun[stage] = true;
  this->Times[stage] = milliseconds;
}

void StageClock::Resolve()
{
  for (int stage = 0; this->Timing && stage < stage::Count; ++stage)
  {
    if (this->Timers[stage].IsAllocated())
    {
      const double ms = this->Timers[stage].Milliseconds();
      this->Times[stage] = this->DidRun[stage] ? ms : 0.0;
    }
  }
}

void StageClock::ReleaseGraphicsResources()
{
  for (auto& timer : this->Timers)
  {
    timer.Release();
  }
}

}
