# Generates from Source/VoxelGISettings.json, the single list of the pass's settings, everything
# that states them in C++ (script mode: -DINPUT=<json> -DOUTPUT_DIR=<directory>):
# - vtkVoxelGIPassSettings.h: vtkVoxelGIPass's base class, public and wrapped: each setting's
#   documented Set/Get block (clamped to its range; doubles refuse NaN; bools with On/Off;
#   enumerations with their enum and Set<Name>To<Label>()), its range getters and its member,
#   initialised to its default. A power_of_two setting's setter is only declared: it is written
#   by hand (vtkVoxelGIPassSettings.cxx), as is PrintSelf, which prints the table.
# - SettingsSnapshot.h/.cxx (internal): voxelgi::Settings, the settings as the stages read them,
#   the enumerations' constants, and SnapshotSettings(pass), which fills it from a pass.
# - vtkVoxelGISettings.cxx: vtkVoxelGISettings' table and access by name.
cmake_policy(VERSION 3.16)
include("${CMAKE_CURRENT_LIST_DIR}/SettingsTable.cmake")
file(READ "${INPUT}" json)
voxelgi_settings_count("${json}" count)
math(EXPR last "${count} - 1")
set(entries "")
set(getters "")
set(setters "")
set(blocks "")       # vtkVoxelGIPassSettings.h: public declarations
set(members "")      # vtkVoxelGIPassSettings.h: members
set(enums "")        # SettingsSnapshot.h: the enumerations' constants
set(fields "")       # SettingsSnapshot.h: voxelgi::Settings
set(fill "")         # SettingsSnapshot.cxx
foreach (i RANGE ${last})
  voxelgi_read_setting(json ${i})
  if (NOT type MATCHES "^(bool|int|double|enum)$")
    message(FATAL_ERROR "${INPUT}: ${name} has the type \"${type}\" (bool, int, double or enum)")
  endif ()
  if (details STREQUAL "")
    message(FATAL_ERROR "${INPUT}: ${name} has no \"details\" (the header's documentation)")
  endif ()
  if (power_of_two AND NOT type STREQUAL "int")
    message(FATAL_ERROR "${INPUT}: ${name} is power_of_two but not an int")
  endif ()

  # the C++ texts of the range and default
  foreach (field min max default)
    voxelgi_number("${${field}}" ${field}_cxx)
  endforeach ()
  if (type STREQUAL "enum")
    if (enum_name STREQUAL "" OR constant_prefix STREQUAL "")
      message(FATAL_ERROR "${INPUT}: the enumeration ${name} needs \"enum\" (the C++ enum's name) "
                          "and \"constant_prefix\" (its constants' prefix)")
    endif ()
    list(LENGTH values labels)
    math(EXPR expected "${max} - ${min} + 1")
    if (NOT labels EQUAL expected)
      message(FATAL_ERROR "${INPUT}: ${name} has ${labels} labels for the values ${min} ... ${max}")
    endif ()
    set(constants "")
    set(shortcuts "")
    set(value ${min})
    foreach (label IN LISTS values)
      voxelgi_enum_constant("${constant_prefix}" "${label}" constant)
      string(APPEND constants "    ${constant} = ${value},\n")
      string(APPEND shortcuts
        "  void Set${name}To${label}() { this->Set${name}(${constant}); }\n")
      if (value EQUAL min)
        set(min_cxx ${constant})
      endif ()
      if (value EQUAL max)
        set(max_cxx ${constant})
      endif ()
      if (value EQUAL default)
        set(default_cxx ${constant})
      endif ()
      math(EXPR value "${value} + 1")
    endforeach ()
    string(REGEX REPLACE ",\n$" "\n" constants "${constants}")
    string(APPEND blocks "  enum ${enum_name}\n  {\n${constants}  };\n\n")
    string(REPLACE "    " "  " internal_constants "${constants}")
    string(APPEND enums "/// ${name}'s values (vtkVoxelGIPass::${constant_prefix}_*).\nenum ${enum_name}\n{\n${internal_constants}};\n\n")
  endif ()

  voxelgi_comment("${details}" "  " comment)
  string(APPEND blocks "  ///@{\n  /**\n${comment}   */\n")
  if (type STREQUAL "bool")
    string(APPEND blocks "  vtkVoxelGISetBoolMacro(${name});\n"
                         "  vtkGetMacro(${name}, vtkTypeBool);\n"
                         "  vtkBooleanMacro(${name}, vtkTypeBool);\n")
    set(member_type vtkTypeBool)
    set(field_type bool)
    if (default)
      set(field_default true)
    else ()
      set(field_default false)
    endif ()
    string(APPEND fill "  c.${name} = pass->Get${name}() != 0;\n")
  else ()
    if (type STREQUAL "double")
      set(member_type double)
      string(APPEND blocks
        "  vtkVoxelGISetClampMacro(${name}, double, ${min_cxx}, ${max_cxx});\n")
    elseif (power_of_two)
      set(member_type int)
      string(APPEND blocks
        "  virtual void Set${name}(int value);\n")
    else ()
      set(member_type int)
      string(APPEND blocks
        "  vtkSetClampMacro(${name}, int, ${min_cxx}, ${max_cxx});\n")
    endif ()
    string(APPEND blocks "  vtkGetMacro(${name}, ${member_type});\n")
    if (power_of_two)
      string(APPEND blocks
        "  virtual int Get${name}MinValue() { return ${min_cxx}; }\n"
        "  virtual int Get${name}MaxValue() { return ${max_cxx}; }\n")
    endif ()
    if (type STREQUAL "enum")
      string(APPEND blocks "${shortcuts}")
    endif ()
    set(field_type ${member_type})
    set(field_default ${default_cxx})
    string(APPEND fill "  c.${name} = pass->Get${name}();\n")
  endif ()
  string(APPEND blocks "  ///@}\n\n")
  string(APPEND members "  ${member_type} ${name} = ${default_cxx};\n")
  string(APPEND fields "  ${field_type} ${name} = ${field_default};\n")

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
string(REGEX REPLACE "\n\n$" "\n" blocks "${blocks}")
string(REGEX REPLACE "\n\n$" "\n" enums "${enums}")

set(content "// Generated from VoxelGISettings.json by GenerateSettings.cmake. Do not edit: change the table.
/**
 * @class   vtkVoxelGIPassSettings
 * @brief   The settings of vtkVoxelGIPass, generated from its settings table.
 *
 * vtkVoxelGIPass's base class, generated at build time from Source/VoxelGISettings.json, the
 * single list of the pass's settings: each setting's Set/Get pair with its documentation, its
 * range and its default. Setters clamp to the setting's range (Get<Name>MinValue(),
 * Get<Name>MaxValue()); doubles refuse NaN with a warning that names the setting; booleans
 * store 0 or 1 and have <Name>On()/<Name>Off(); enumerations have their constants and Set<Name>To<Value>().
 * Use them through vtkVoxelGIPass; vtkVoxelGISettings lists them by name.
 *
 * @sa vtkVoxelGIPass vtkVoxelGISettings
 */
#ifndef vtkVoxelGIPassSettings_h
#define vtkVoxelGIPassSettings_h

#include \"vtkOpenGLRenderPass.h\"
#include \"vtkRenderingVoxelGIModule.h\" // for export macro

#include <cmath> // for std::isnan

// vtkSetClampMacro that refuses NaN (which passes any clamp) with a message naming the
// setting, keeping its value.
#define vtkVoxelGISetClampMacro(name, type, min, max)                                          \\
  virtual void Set##name(type _arg)                                                            \\
  {                                                                                            \\
    if (std::isnan(_arg))                                                                      \\
    {                                                                                          \\
      vtkWarningMacro(<< #name \" cannot be NaN; it stays \" << this->name << \".\");             \\
      return;                                                                                  \\
    }                                                                                          \\
    const type clamped = _arg < min ? min : (_arg > max ? max : _arg);                         \\
    if (this->name != clamped)                                                                 \\
    {                                                                                          \\
      this->name = clamped;                                                                    \\
      this->Modified();                                                                        \\
    }                                                                                          \\
  }                                                                                            \\
  virtual type Get##name##MinValue() { return min; }                                           \\
  virtual type Get##name##MaxValue() { return max; }

// A boolean stored as 0 or 1, whatever non-zero value it is given (C, Python, ParaView).
#define vtkVoxelGISetBoolMacro(name)                                                           \\
  virtual void Set##name(vtkTypeBool _arg)                                                     \\
  {                                                                                            \\
    const vtkTypeBool value = _arg != 0 ? 1 : 0;                                               \\
    if (this->name != value)                                                                   \\
    {                                                                                          \\
      this->name = value;                                                                      \\
      this->Modified();                                                                        \\
    }                                                                                          \\
  }

class VTKRENDERINGVOXELGI_EXPORT vtkVoxelGIPassSettings : public vtkOpenGLRenderPass
{
public:
  vtkAbstractTypeMacro(vtkVoxelGIPassSettings, vtkOpenGLRenderPass);
  /// Every setting of the table, so that none can be forgotten.
  void PrintSelf(ostream& os, vtkIndent indent) override;

${blocks}
protected:
  vtkVoxelGIPassSettings() = default;
  ~vtkVoxelGIPassSettings() override = default;

  // Settings, with the table's defaults.
${members}
private:
  vtkVoxelGIPassSettings(const vtkVoxelGIPassSettings&) = delete;
  void operator=(const vtkVoxelGIPassSettings&) = delete;
};

#endif
")
voxelgi_write_if_changed("${OUTPUT_DIR}/vtkVoxelGIPassSettings.h" "${content}")

set(content "// Generated from VoxelGISettings.json by GenerateSettings.cmake. Do not edit: change the table.
#ifndef VoxelGISettingsSnapshot_h
#define VoxelGISettingsSnapshot_h

class vtkVoxelGIPassSettings;

namespace voxelgi
{
${enums}
/// The pass's settings as the stages read them, one member per setting of the table
/// (vtkVoxelGIPassSettings.h documents them), with the table's defaults.
struct Settings
{
${fields}};

/// A pass's settings now.
Settings SnapshotSettings(vtkVoxelGIPassSettings* pass);
}

#endif
")
voxelgi_write_if_changed("${OUTPUT_DIR}/SettingsSnapshot.h" "${content}")

set(content "// Generated from VoxelGISettings.json by GenerateSettings.cmake. Do not edit: change the table.
#include \"SettingsSnapshot.h\"

#include \"vtkVoxelGIPassSettings.h\"

namespace voxelgi
{

Settings SnapshotSettings(vtkVoxelGIPassSettings* pass)
{
  Settings c;
${fill}  return c;
}

}
")
voxelgi_write_if_changed("${OUTPUT_DIR}/SettingsSnapshot.cxx" "${content}")

set(content "// Generated from VoxelGISettings.json by GenerateSettings.cmake. Do not edit.
#include \"vtkVoxelGISettings.h\"
#include \"vtkObjectFactory.h\"
#include \"vtkVoxelGIPassSettings.h\"

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

double vtkVoxelGISettings::GetValue(vtkVoxelGIPassSettings* pass, const char* setting)
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

bool vtkVoxelGISettings::SetValue(vtkVoxelGIPassSettings* pass, const char* setting, double value)
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
voxelgi_write_if_changed("${OUTPUT_DIR}/vtkVoxelGISettings.cxx" "${content}")
