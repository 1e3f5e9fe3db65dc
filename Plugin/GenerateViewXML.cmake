# Generates the ParaView server-manager XML of the Voxel GI render view from
# Source/VoxelGISettings.json (script mode: -DINPUT=... -DOUTPUT=...). Every setting becomes a
# property of the pass proxy, exposed on the view, grouped, with its domain (a range, or a list:
# an enumeration's labels, or the powers of two in the range), its documentation, "advanced"
# visibility where the table says so, and hidden while GI is off.
include("${CMAKE_CURRENT_LIST_DIR}/../Source/SettingsTable.cmake")
file(READ "${INPUT}" json)
voxelgi_settings_count("${json}" count)
math(EXPR last "${count} - 1")
set(properties "")
set(exposed_information "")
set(groups_order General Voxelization Lighting Cones "Debug view" Performance)
foreach (group IN LISTS groups_order)
  set(exposed_${group} "")
endforeach ()
foreach (i RANGE ${last})
  voxelgi_read_setting(json ${i})
  set(visibility "")
  if (advanced)
    set(visibility " panel_visibility=\"advanced\"")
  endif ()
  # Enumerations and powers of two offer a list of values (a combo box): their entries.
  set(entries "")
  if (type STREQUAL "enum")
    set(v 0)
    foreach (label IN LISTS values)
      string(APPEND entries "\n          <Entry text=\"${label}\" value=\"${v}\" />")
      math(EXPR v "${v} + 1")
    endforeach ()
  elseif (power_of_two)
    set(v ${min})
    while (v LESS_EQUAL max)
      string(APPEND entries "\n          <Entry text=\"${v}\" value=\"${v}\" />")
      math(EXPR v "${v} * 2")
    endwhile ()
  endif ()
  if (type STREQUAL "double")
    set(element "DoubleVectorProperty")
    set(domain "<DoubleRangeDomain name=\"range\" min=\"${min}\" max=\"${max}\" />")
  elseif (type STREQUAL "bool")
    set(element "IntVectorProperty")
    set(domain "<BooleanDomain name=\"bool\" />")
  elseif (NOT entries STREQUAL "")
    set(element "IntVectorProperty")
    set(domain "<EnumerationDomain name=\"enum\">${entries}\n        </EnumerationDomain>")
  else ()
    set(element "IntVectorProperty")
    set(domain "<IntRangeDomain name=\"range\" min=\"${min}\" max=\"${max}\" />")
  endif ()
  # Settings other than the switch itself hide while GI is off. The hint sits in the
  # property's own definition: ParaView reads hints there, not on the exposing view, whose
  # name for "Enabled" (EnableVoxelGI) the decorator names.
  set(hints "")
  if (NOT name STREQUAL "Enabled")
    set(hints "
        <Hints>
          <PropertyWidgetDecorator type=\"GenericDecorator\" mode=\"visibility\" property=\"EnableVoxelGI\" value=\"1\" />
        </Hints>")
  endif ()
  # the setting, and an information-only twin that reads the pass back
  string(APPEND properties "      <${element} name=\"${name}\" command=\"Set${name}\" number_of_elements=\"1\" default_values=\"${default}\"${visibility}>
        ${domain}
        <Documentation>${doc}</Documentation>${hints}
      </${element}>
      <${element} name=\"${name}Info\" command=\"Get${name}\" information_only=\"1\" />
")
  # On the view, "Enabled" reads "EnableVoxelGI"; other settings keep their names.
  if (name STREQUAL "Enabled")
    set(exposed "          <Property name=\"Enabled\" exposed_name=\"EnableVoxelGI\" />\n")
  else ()
    set(exposed "          <Property name=\"${name}\" />\n")
  endif ()
  string(APPEND exposed_${group} "${exposed}")
  string(APPEND exposed_information "          <Property name=\"${name}Info\" />\n")
endforeach ()

set(exposed_groups "${exposed_information}          <Property name=\"GIActive\" />
          <Property name=\"RankTrafficBytes\" />
          <Property name=\"RankTrafficMilliseconds\" />
          <Property name=\"Invalidate\" />\n")
foreach (group IN LISTS groups_order)
  if (NOT exposed_${group} STREQUAL "")
    string(APPEND exposed_groups "        <PropertyGroup label=\"Voxel GI: ${group}\">
${exposed_${group}}        </PropertyGroup>
")
  endif ()
endforeach ()

set(content "<!-- Generated from Source/VoxelGISettings.json by Plugin/GenerateViewXML.cmake. -->
<ServerManagerConfiguration>
  <ProxyGroup name=\"voxelgi\">
    <Proxy name=\"VoxelGIPass\" class=\"vtkVoxelGIPass\" label=\"Voxel GI\"
           processes=\"client|renderserver|dataserver\">
      <Documentation>Voxel global illumination render pass (deferred voxel shading).</Documentation>
${properties}      <IntVectorProperty name=\"GIActive\" command=\"GetGIActive\" information_only=\"1\" />
      <DoubleVectorProperty name=\"RankTrafficBytes\" command=\"GetRankTrafficBytes\" information_only=\"1\" />
      <DoubleVectorProperty name=\"RankTrafficMilliseconds\" command=\"GetRankTrafficMilliseconds\" information_only=\"1\" />
      <Property name=\"Invalidate\" command=\"Invalidate\" panel_visibility=\"never\" />
    </Proxy>
  </ProxyGroup>
  <ProxyGroup name=\"views\">
    <RenderViewProxy name=\"VoxelGIRenderView\" class=\"vtkPVVoxelGIView\"
        label=\"Render View (Voxel GI)\" processes=\"client|renderserver|dataserver\"
        base_proxygroup=\"views\" base_proxyname=\"RenderView\">
      <Documentation>
        A render view with real-time voxel global illumination: indirect diffuse and specular
        light and ambient occlusion from cone tracing voxelized geometry, and the lights'
        shadows.
      </Documentation>
      <SubProxy command=\"SetGIPass\">
        <Proxy name=\"VoxelGI\" proxygroup=\"voxelgi\" proxyname=\"VoxelGIPass\" />
        <ExposedProperties>
${exposed_groups}        </ExposedProperties>
      </SubProxy>
    </RenderViewProxy>
  </ProxyGroup>
</ServerManagerConfiguration>
")
voxelgi_write_if_changed("${OUTPUT}" "${content}")
