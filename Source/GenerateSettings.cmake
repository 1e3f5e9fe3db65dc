# Generates vtkVoxelGISettings' table and accessors from Source/VoxelGISettings.json, the
# single list of the pass's settings (script mode: -DINPUT=... -DOUTPUT=...).
include("${CMAKE_CURRENT_LIST_DIR}/SettingsTable.cmake")
file(READ "${INPUT}" json)
voxelgi_settings_count("${json}" count)
math(EXPR last "${count} - 1")
set(entries "")
set(getters "")
set(setters "")
foreach (i RANGE ${last})
  voxelgi_read_setting(json ${i})
  set(labels "")
  foreach (label IN LISTS values)
    string(APPEND labels "${label}|")
  endforeach ()
  string(REPLACE "\"" "\\\"" doc "${doc}")
  string(TOLOWER "${power_of_two}" power_of_two) # TRUE/FALSE to C++
  string(APPEND entries
    "  { \"${name}\", \"${type}\", ${min}, ${max}, ${default}, ${power_of_two}, \"${group}\", \"${labels}\", \"${doc}\" },\n")
  if (type STREQUAL "double")
    string(APPEND getters "  if (name == \"${name}\") return pass->Get${name}();\n")
    string(APPEND setters "  if (name == \"${name}\") { pass->Set${name}(value); return true; }\n")
  else ()
    string(APPEND getters "  if (name == \"${name}\") return static_cast<double>(pass->Get${name}());\n")
    string(APPEND setters "  if (name == \"${name}\") { pass->Set${name}(static_cast<int>(std::lround(value))); return true; }\n")
  endif ()
endforeach ()
set(content "// Generated from VoxelGISettings.json by GenerateSettings.cmake. Do not edit.
#include \"vtkVoxelGISettings.h\"
#include \"vtkObjectFactory.h\"
#include \"vtkVoxelGIPass.h\"

#include \"VoxelGrid.h\" // for voxelgi::ClampResolution

#include <algorithm>
#include <cmath>
#include <string>

namespace
{
struct Entry
{
  const char* Name;
  const char* Type;
  double Minimum;
  double Maximum;
  double Default;
  bool PowerOfTwo;
  const char* Group;
  const char* Values;
  const char* Documentation;
};
const Entry Table[] = {
${entries}};
}

vtkStandardNewMacro(vtkVoxelGISettings);

void vtkVoxelGISettings::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  for (const Entry& e : Table)
  {
    os << indent << e.Name << \" (\" << e.Type << \", \" << e.Group << \"): default \" << e.Default
       << \", range [\" << e.Minimum << \", \" << e.Maximum << \"]\\n\";
  }
}

int vtkVoxelGISettings::GetNumberOfSettings()
{
  return static_cast<int>(sizeof(Table) / sizeof(Table[0]));
}

#define VOXELGI_FIELD(method, type, field, fallback)                                            \\
  type vtkVoxelGISettings::method(int i)                                                      \\
  {                                                                                            \\
    return (i >= 0 && i < GetNumberOfSettings()) ? Table[i].field : fallback;                  \\
  }
VOXELGI_FIELD(GetName, const char*, Name, \"\")
VOXELGI_FIELD(GetType, const char*, Type, \"\")
VOXELGI_FIELD(GetMinimum, double, Minimum, 0.0)
VOXELGI_FIELD(GetMaximum, double, Maximum, 0.0)
VOXELGI_FIELD(GetDefault, double, Default, 0.0)
VOXELGI_FIELD(GetPowerOfTwo, bool, PowerOfTwo, false)
VOXELGI_FIELD(GetGroup, const char*, Group, \"\")
VOXELGI_FIELD(GetEnumerationValues, const char*, Values, \"\")
VOXELGI_FIELD(GetDocumentation, const char*, Documentation, \"\")
#undef VOXELGI_FIELD

int vtkVoxelGISettings::NearestPowerOfTwo(int i, int value)
{
  // the pass's own rounding, so that a user interface offers what the pass will use
  return voxelgi::ClampResolution(
    value, static_cast<int>(GetMinimum(i)), static_cast<int>(GetMaximum(i)));
}

int vtkVoxelGISettings::GetIndex(const char* setting)
{
  for (int i = 0; setting && i < GetNumberOfSettings(); ++i)
  {
    if (std::string(Table[i].Name) == setting)
    {
      return i;
    }
  }
  return -1;
}

double vtkVoxelGISettings::GetValue(vtkVoxelGIPass* pass, const char* setting)
{
  const std::string name = setting ? setting : \"\";
  if (!pass)
  {
    return 0.0;
  }
  if (GetIndex(setting) < 0)
  {
    vtkGenericWarningMacro(<< \"vtkVoxelGISettings::GetValue: no setting named \\\"\" << name
                           << \"\\\"; returning 0.\");
    return 0.0;
  }
${getters}  return 0.0;
}

bool vtkVoxelGISettings::SetValue(vtkVoxelGIPass* pass, const char* setting, double value)
{
  const std::string name = setting ? setting : \"\";
  const int i = GetIndex(setting);
  if (!pass)
  {
    return false;
  }
  if (i < 0)
  {
    vtkGenericWarningMacro(<< \"vtkVoxelGISettings::SetValue: no setting named \\\"\" << name
                           << \"\\\"; nothing was set.\");
    return false;
  }
  if (std::isnan(value))
  {
    vtkGenericWarningMacro(<< \"vtkVoxelGISettings::SetValue: \" << name
                           << \" cannot be NaN; it stays \" << GetValue(pass, setting) << \".\");
    return false;
  }
  // Clamped in double first: an integer conversion of 1e30, Inf or 3e9 would wrap.
  value = std::min(std::max(value, Table[i].Minimum), Table[i].Maximum);
${setters}  return false;
}
")
voxelgi_write_if_changed("${OUTPUT}" "${content}")
