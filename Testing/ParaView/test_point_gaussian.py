"""ParaView's Point Gaussian representation with a splat shape takes part in GI (pvpython,
builtin session, under Xvfb): the points of a sphere source drawn as the "Sphere" preset's
splats over a floor, under one scene light. ParaView hands the splat mapper a composite
dataset; the splats are voxelized as spheres of the representation's radius, so with GI the
floor under them darkens (their shadow and AO) against the same view with GI off, GI is
active, and the image matches the baseline.

    pvpython test_point_gaussian.py PLUGIN BASELINE OUTPUT_DIR
"""
import os
import sys

from paraview.simple import (AddLight, CreateView, Delete, LoadPlugin, Plane, Render,
                             SaveScreenshot, Show, Sphere)

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

points = Sphere(Center=[0, 2, 0], Radius=2.5, ThetaResolution=10, PhiResolution=8)
display = Show(points, view)
display.SetRepresentationType("Point Gaussian")
display.ShaderPreset = "Sphere"
display.GaussianRadius = 0.4
floor = Plane(Origin=[-8, -1.5, -8], Point1=[8, -1.5, -8], Point2=[-8, -1.5, 8])
Show(floor, view)
view.CameraPosition = [12, 10, 18]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 1, 0]

failures = []


def screenshot(name):
    Render(view)
    path = os.path.join(output_dir, name)
    SaveScreenshot(path, view, ImageResolution=[300, 300])
    return path


def mean(path, box):
    """Mean brightness of the pixels in box (x0, y0, x1, y1; y up, as VTK's rows)."""
    return rgb(path).reshape(300, 300, 3)[box[1]:box[3], box[0]:box[2]].mean()


view.EnableVoxelGI = 0
plain = screenshot("ParaViewPointGaussian-plain.png")
view.EnableVoxelGI = 1
rendered = screenshot("ParaViewPointGaussian.png")
view.SMProxy.UpdatePropertyInformation()
if not view.SMProxy.GetProperty("GIActive").GetElement(0):
    failures.append("GI did not run in the view")
# the floor where the splats' shadow falls, against the open floor (GI adds light there)
shadow, open_floor = (130, 110, 170, 118), (200, 60, 240, 90)
ratio = (mean(rendered, shadow) / mean(plain, shadow)) / \
    (mean(rendered, open_floor) / mean(plain, open_floor))
print("floor under the splats with GI: %.2f of plain VTK's, relative to the open floor" % ratio)
if ratio > 0.8:
    failures.append("the floor under the splats is not darkened: the splats take no part in GI")

problem = mismatch(baseline, rendered, output_dir)
if problem:
    failures.append(problem)

# ParaView 5.11's pvpython crashes in sys.exit() while views are alive
Delete(view)
del view
for failure in failures:
    print("FAILED:", failure)
sys.exit(1 if failures else 0)
