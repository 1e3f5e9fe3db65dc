/**
 * @class   vtkVoxelGISettings
 * @brief   The table of vtkVoxelGIPass's settings, and access to them by name.
 *
 * Generated at build time from Source/VoxelGISettings.json, the single list of the pass's
 * settings (name, type, range, default, group, enumeration labels, documentation, whether
 * only powers of two are taken), which the C++ setters, the Qt panel and the ParaView XML
 * follow. User interfaces build their controls from it and read or write a pass's settings
 * with GetValue()/SetValue().
 *
 * @sa vtkVoxelGIPass
 */
#ifndef vtkVoxelGISettings_h
#define vtkVoxelGISettings_h

#include "vtkObject.h"
#include "vtkRenderingVoxelGIModule.h" // for export macro

class vtkVoxelGIPassSettings;

class VTKRENDERINGVOXELGI_EXPORT vtkVoxelGISettings : public vtkObject
{
public:
  static vtkVoxelGISettings* New();
  vtkTypeMacro(vtkVoxelGISettings, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  static int GetNumberOfSettings();
  /**
   * Setting i's name (as in Set<Name>/Get<Name>), type ("bool", "int", "double" or "enum"),
   * range, default, group, enumeration labels ("A|B|C|", empty unless an enum) and
   * one-line documentation.
   */
  static const char* GetName(int i);
  static const char* GetType(int i);
  static double GetMinimum(int i);
  static double GetMaximum(int i);
  static double GetDefault(int i);
  static const char* GetGroup(int i);
  static const char* GetEnumerationValues(int i);
  static const char* GetDocumentation(int i);

  /**
   * Whether setting i takes only the powers of two in its range, and the one of those nearest
   * to `value` (as the pass rounds it), for user interfaces that offer only what the pass uses.
   */
  static bool GetPowerOfTwo(int i);
  static int NearestPowerOfTwo(int i, int value);

  /**
   * Setting `name`'s index in the table, -1 for an unknown name.
   */
  static int GetIndex(const char* name);
  /**
   * Read or write a setting of `pass` by name. SetValue clamps to the setting's range in
   * double precision, then rounds integers and booleans, and the pass's setter applies its
   * own rules (powers of two); it returns false, with a warning that names the setting, for
   * an unknown name or NaN (the setting keeps its value). GetValue warns about an unknown
   * name and returns 0.
   */
  static double GetValue(vtkVoxelGIPassSettings* pass, const char* name);
  static bool SetValue(vtkVoxelGIPassSettings* pass, const char* name, double value);

protected:
  vtkVoxelGISettings() = default;
  ~vtkVoxelGISettings() override = default;

private:
  vtkVoxelGISettings(const vtkVoxelGISettings&) = delete;
  void operator=(const vtkVoxelGISettings&) = delete;
};

#endif
