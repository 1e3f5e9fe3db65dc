// The hand-written part of the generated settings class (vtkVoxelGIPassSettings.h, from
// VoxelGISettings.json): the setter of a power-of-two setting, and printing the table.
#include "vtkVoxelGIPassSettings.h"

#include "VoxelGrid.h"
#include "VoxelizePass.h"
#include "vtkVoxelGISettings.h"

#include <sstream>

void vtkVoxelGIPassSettings::SetVoxelResolution(int resolution)
{
  const int minimum = this->GetVoxelResolutionMinValue();
  const int maximum = this->GetVoxelResolutionMaxValue();
  const int clamped = voxelgi::ClampResolution(resolution, minimum, maximum);
  if (clamped != resolution)
  {
    std::ostringstream message;
    message << "VoxelResolution " << resolution << " is not a power of two in [" << minimum
            << ", " << maximum << "]";
    if (resolution > maximum)
    {
      message << " (it would need "
              << voxelgi::VoxelizePass::RequiredBytes(resolution, false) / (1024 * 1024)
              << " MiB of voxel memory)";
    }
    vtkWarningMacro(<< message.str() << "; using " << clamped << ".");
  }
  if (clamped != this->VoxelResolution)
  {
    this->VoxelResolution = clamped;
    this->Modified();
  }
}

void vtkVoxelGIPassSettings::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  for (int i = 0; i < vtkVoxelGISettings::GetNumberOfSettings(); ++i)
  {
    const char* name = vtkVoxelGISettings::GetName(i);
    os << indent << name << ": " << vtkVoxelGISettings::GetValue(this, name) << "\n";
  }
}
