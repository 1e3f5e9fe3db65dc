"""ParaView representations on an unstructured grid take part in GI (pvpython, builtin
session, under Xvfb): the cells of the Wavelet source above a threshold (an unstructured
grid, as Threshold and Clip give), shown as a Surface coloured by RTData through a lookup
table, over a floor, under one scene light. The GI view's image against the same view with
GI off: the floor under the grid darkens (its AO and shadow come from the grid's voxels),
GI is active, and the image matches the baseline.

    pvpython test_unstructured.py PLUGIN BASELINE OUTPUT_DIR
"""
import os
import sys

from paraview.simple import (AddLight, ColorBy, CreateView, Delete, LoadPlugin, Plane,
                             Render, SaveScreenshot, Show, Threshold, Wavelet)

plugin, baseline, output_dir = [os.path.abspath(a) for a in sys.argv[1:4]]
os.makedirs(output_dir, exist_ok=True)
LoadPlugin(plugin, ns=globals())
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from strict_image import mismatch, rgb  # noqa: E402

view = CreateView("VoxelGIRenderView")
view.ViewSize = [300, 300]
view.OrientationAxesVisibility = 0
view.VoxelResolution = 64
view.UseLight = 0  # no headlight: one scene light above casts the shadows
light = AddLight(view=view)
light.Coords = "Scene"
light.Type = "Directional"
light.Position = [10, 40, 20]
light.FocalPoint = [0, 0, 0]

grid = Threshold(Input=Wavelet(), Scalars=["POINTS", "RTData"])
grid.LowerThreshold, grid.UpperThreshold = 200.0, 300.0
display = Show(grid, view)
display.Representation = "Surface"
ColorBy(display, ("POINTS", "RTData"))
floor = Plane(Origin=[-20, -11, -20], Point1=[20, -11, -20], Point2=[-20, -11, 20])
Show(floor, view)
view.CameraPosition = [30, 25, 45]
view.CameraFocalPoint = [0, -5, 0]
view.CameraViewUp = [0, 1, 0]

failures = []
grid_data = grid.GetClientSideObject().GetOutputDataObject(0)
if grid_data.GetClassName() != "vtkUnstructuredGrid" or grid_data.GetNumberOfCells() == 0:
    failures.append("the threshold gave %d cells of a %s" %
                    (grid_data.GetNumberOfCells(), grid_data.GetClassName()))


def screenshot(name):
    Render(view)
    path = os.path.join(output_dir, name)
    SaveScreenshot(path, view, ImageResolution=[300, 300])
    return path


def floor_mean(path, box):
    """Mean brightness of the pixels in box (x0, y0, x1, y1; y up, as VTK's rows)."""
    return rgb(path).reshape(300, 300, 3)[box[1]:box[3], box[0]:box[2]].mean()


view.EnableVoxelGI = 0
plain = screenshot("ParaViewUnstructured-plain.png")
view.EnableVoxelGI = 1
rendered = screenshot("ParaViewUnstructured.png")
view.SMProxy.UpdatePropertyInformation()
if not view.SMProxy.GetProperty("GIActive").GetElement(0):
    failures.append("GI did not run in the view")
# the floor under the grid, where its shadow falls
box = (120, 112, 170, 132)
darker = 1.0 - floor_mean(rendered, box) / floor_mean(plain, box)
print("floor under the grid: %.1f %% darker with GI" % (100.0 * darker))
if darker < 0.05:
    failures.append("the floor under the grid is not darkened: the grid takes no part in GI")

problem = mismatch(baseline, rendered, output_dir)
if problem:
    failures.append(problem)

# ParaView 5.11's pvpython crashes in sys.exit() while views are alive
Delete(view)
del view
for failure in failures:
    print("FAILED:", failure)
sys.exit(1 if failures else 0)
