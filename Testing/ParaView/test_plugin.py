"""ParaView plugin test (pvpython, builtin session, under Xvfb):
loads the plugin, creates the "Render View (Voxel GI)", shows a contour of the Wavelet source
over a floor, sets view properties, renders and compares the screenshot with a baseline
through vtkTesting; checks that an outline says nothing and that a Volume representation takes
part in GI; then checks that every setting of the settings table is a property of
the view and reaches the pass, and that a power-of-two setting offers only powers of two.

    pvpython test_plugin.py PLUGIN SETTINGS_JSON BASELINE OUTPUT_DIR
"""
import json
import os
import sys

from paraview.vtk import vtkOutputWindow, vtkStringOutputWindow
from paraview.simple import (Contour, CreateView, Delete, GetDisplayProperties, Hide, LoadPlugin,
                             Plane, Render, SaveScreenshot, Show, Wavelet)

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from strict_image import mismatch  # noqa: E402

plugin, table_path, baseline, output_dir = [os.path.abspath(a) for a in sys.argv[1:5]]
os.makedirs(output_dir, exist_ok=True)
LoadPlugin(plugin, ns=globals())

view = CreateView("VoxelGIRenderView")
view.ViewSize = [300, 300]
view.OrientationAxesVisibility = 0
view.VoxelResolution = 64
view.AmbientOcclusionStrength = 0.8

wavelet = Wavelet()
contour = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[190.0])
display = Show(contour, view)
display.ColorArrayName = ["POINTS", ""]
display.DiffuseColor = [0.9, 0.5, 0.2]
floor = Plane(Origin=[-16, -11, -16], Point1=[16, -11, -16], Point2=[-16, -11, 16])
Show(floor, view)
view.CameraPosition = [30, 20, 45]
view.CameraFocalPoint = [0, -3, 0]
view.CameraViewUp = [0, 1, 0]
Render(view)

# The pass is the view's "VoxelGI" sub-proxy; its information-only properties, exposed on
# the view, read the pass back.
def pass_value(name):
    view.SMProxy.UpdatePropertyInformation()
    return view.SMProxy.GetProperty(name).GetElement(0)


failures = []
if not pass_value("GIActive"):
    failures.append("GI did not run in the view")

rendered = os.path.join(output_dir, "ParaViewVoxelGIView-rendered.png")
SaveScreenshot(rendered, view, ImageResolution=[300, 300])
problem = mismatch(baseline, rendered, output_dir)
if problem:
    failures.append(problem)

# ParaView's default representation of image data, an outline (lines in a wireframe actor),
# is drawn as VTK draws it without a warning or an OpenGL error (either opens ParaView's
# message window; the voxelization's geometry shader refuses lines).
previous = vtkOutputWindow.GetInstance()
previous.Register(None)
captured = vtkStringOutputWindow()
vtkOutputWindow.SetInstance(captured)
Show(wavelet, view)
Render(view)
vtkOutputWindow.SetInstance(previous)
if GetDisplayProperties(wavelet, view).Representation != "Outline":
    failures.append("the Wavelet is not shown as an outline")
if "voxel GI" in captured.GetOutput() or "error" in captured.GetOutput().lower():
    failures.append("showing an outline said: " + captured.GetOutput())

# The Volume representation (a vtkVolume on the image data) takes part in GI: no notice
# leaves it to VTK, and GI runs.
captured = vtkStringOutputWindow()
vtkOutputWindow.SetInstance(captured)
GetDisplayProperties(wavelet, view).SetRepresentationType("Volume")
Render(view)
vtkOutputWindow.SetInstance(previous)
if "without voxel GI" in captured.GetOutput() or not pass_value("GIActive"):
    failures.append("the Volume representation is left out: " + captured.GetOutput())
Hide(wavelet, view)

# every setting of the table is a view property that reaches the pass, and hides in the
# panel while GI is off (a decorator on the view's EnableVoxelGI)
with open(table_path) as f:
    table = json.load(f)["settings"]
for s in table:
    name = s["name"]
    prop = "EnableVoxelGI" if name == "Enabled" else name
    if prop not in view.ListProperties():
        failures.append("view has no property " + prop)
        continue
    hints = view.SMProxy.GetProperty(prop).GetHints()
    decorator = hints.FindNestedElementByName("PropertyWidgetDecorator") if hints else None
    hides = decorator is not None and decorator.GetAttribute("property") == "EnableVoxelGI" \
        and decorator.GetAttribute("mode") == "visibility" and decorator.GetAttribute("value") == "1"
    if hides == (name == "Enabled"):
        failures.append("%s %s while GI is off" % (prop, "hides" if name == "Enabled" else "shows"))
    if s.get("power_of_two"):
        domain = view.SMProxy.GetProperty(prop).FindDomain("vtkSMEnumerationDomain")
        count = domain.GetNumberOfEntries() if domain else 0
        offered = [domain.GetEntryValue(i) for i in range(count)]
        powers = [2 ** k for k in range(31) if s["min"] <= 2 ** k <= s["max"]]
        if offered != powers:
            failures.append("%s offers %s, not the powers of two %s" % (prop, offered, powers))
    if s["type"] in ("bool",):
        value = 0 if s["default"] else 1
    elif s["type"] in ("int", "enum"):
        value = s["max"] if s["default"] != s["max"] else s["min"]
    else:
        value = 0.5 * (s["min"] + s["max"])
    setattr(view, prop, value)
    view.UpdateVTKObjects()
    got = pass_value(name + "Info")
    if abs(got - value) > 1e-9 * max(1.0, abs(value)):
        failures.append("%s = %s on the view, %s on the pass" % (prop, value, got))
    setattr(view, prop, s["default"])
    view.UpdateVTKObjects()

# ParaView 5.11's pvpython crashes in sys.exit() while views are alive (its own Render View too)
Delete(view)
del view

for failure in failures:
    print("FAILED:", failure)
print("%d settings checked, %d failures" % (len(table), len(failures)))
sys.exit(1 if failures else 0)
