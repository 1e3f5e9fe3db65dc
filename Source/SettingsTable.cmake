# Reads the settings table, Source/VoxelGISettings.json, for the generators (GenerateSettings.cmake,
# Plugin/GenerateViewXML.cmake), so that they read it the same way.
#
# voxelgi_write_if_changed(<path> <content>): writes only when the content differs, so that
# what depends on the generated file is not rebuilt for nothing.
# voxelgi_settings_count(<json> <out>): number of settings.
# voxelgi_read_setting(<json variable> <i>): sets name, type, default, group, doc, min, max (0 and 1 for
# bool; empty when the table has none), advanced and power_of_two (TRUE/FALSE) and values (the
# enumeration's labels, a list) to setting <i>'s entries.
function (voxelgi_settings_count json out)
  string(JSON count LENGTH "${json}" settings)
  set(${out} ${count} PARENT_SCOPE)
endfunction ()

macro (voxelgi_read_setting json_var i)
  foreach (field name type default group doc)
    string(JSON ${field} GET "${${json_var}}" settings ${i} ${field})
  endforeach ()
  foreach (field min max)
    string(JSON ${field} ERROR_VARIABLE _voxelgi_missing GET "${${json_var}}" settings ${i} ${field})
    if (_voxelgi_missing)
      set(${field} "")
    endif ()
  endforeach ()
  if (type STREQUAL "bool")
    set(min 0)
    set(max 1)
  endif ()
  foreach (field advanced power_of_two)
    string(JSON ${field} ERROR_VARIABLE _voxelgi_missing GET "${${json_var}}" settings ${i} ${field})
    if (_voxelgi_missing OR NOT ${field})
      set(${field} FALSE)
    else ()
      set(${field} TRUE)
    endif ()
  endforeach ()
  set(values "")
  string(JSON _voxelgi_value_count ERROR_VARIABLE _voxelgi_missing LENGTH "${${json_var}}" settings ${i} values)
  if (NOT _voxelgi_missing AND _voxelgi_value_count GREATER 0)
    math(EXPR _voxelgi_last_value "${_voxelgi_value_count} - 1")
    foreach (_voxelgi_v RANGE ${_voxelgi_last_value})
      string(JSON _voxelgi_label GET "${${json_var}}" settings ${i} values ${_voxelgi_v})
      list(APPEND values "${_voxelgi_label}")
    endforeach ()
  endif ()
endmacro ()

function (voxelgi_write_if_changed path content)
  set(old "")
  if (EXISTS "${path}")
    file(READ "${path}" old)
  endif ()
  if (NOT old STREQUAL content)
    file(WRITE "${path}" "${content}")
  endif ()
endfunction ()
