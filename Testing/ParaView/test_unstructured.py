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

from paraview.simple import ColorBy, Plane, Show, Threshold, Wavelet

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sunlit_view  # noqa: E402

view, baseline, output_dir = sunlit_view.start(sys.argv[1:4])
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

plain, rendered = sunlit_view.screenshots(view, output_dir, "ParaViewUnstructured", failures)
# the floor under the grid, where its shadow falls
box = (120, 112, 170, 132)
darker = 1.0 - sunlit_view.mean(rendered, box) / sunlit_view.mean(plain, box)
print("floor under the grid: %.1f %% darker with GI" % (100.0 * darker))
if darker < 0.05:
    failures.append("the floor under the grid is not darkened: the grid takes no part in GI")

status = sunlit_view.finish(view, baseline, rendered, output_dir, failures)
del view
sys.exit(status)
