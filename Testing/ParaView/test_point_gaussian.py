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

from paraview.simple import Plane, Show, Sphere

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sunlit_view  # noqa: E402

view, baseline, output_dir = sunlit_view.start(sys.argv[1:4])
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
plain, rendered = sunlit_view.screenshots(view, output_dir, "ParaViewPointGaussian", failures)
# the floor where the splats' shadow falls, against the open floor (GI adds light there)
shadow, open_floor = (130, 110, 170, 118), (200, 60, 240, 90)
ratio = (sunlit_view.mean(rendered, shadow) / sunlit_view.mean(plain, shadow)) / \
    (sunlit_view.mean(rendered, open_floor) / sunlit_view.mean(plain, open_floor))
print("floor under the splats with GI: %.2f of plain VTK's, relative to the open floor" % ratio)
if ratio > 0.8:
    failures.append("the floor under the splats is not darkened: the splats take no part in GI")

status = sunlit_view.finish(view, baseline, rendered, output_dir, failures)
del view
sys.exit(status)
