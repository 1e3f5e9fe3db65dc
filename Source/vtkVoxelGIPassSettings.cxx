// The hand-written part of the generated settings class (vtkVoxelGIPassSettings.h, from
// VoxelGISettings.json): the setter of a power-of-two setting, and printing the table.
#include "vtkVoxelGIPassSettings.h"

#include "VoxelGrid.h"
#include "VoxelizePass.h"
#include "vtkVoxelGISettings.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

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
              << voxelgi::VoxelizePass::RequiredBytes(resolution, false, false) / (1024 * 1024)
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
    const double value = vtkVoxelGISettings::GetValue(this, name);
    os << indent << name << ": ";
    // An enumeration prints its value's name, as its setter's ...To<Name>() says it.
    const std::string type = vtkVoxelGISettings::GetType(i);
    if (type == "enum")
    {
      std::istringstream values(vtkVoxelGISettings::GetEnumerationValues(i));
      std::vector<std::string> labels;
      for (std::string label; std::getline(values, label, '|');)
      {
        labels.push_back(label);
      }
      const auto k = static_cast<std::size_t>(std::lround(value));
      os << (k < labels.size() ? labels[k] : "?") << " (" << value << ")\n";
    }
    else if (type == "bool")
    {
      os << (value != 0.0 ? "On" : "Off") << "\n";
    }
    else
    {
      os << value << "\n";
    }
  }
}
