"""What the ParaView tests of one representation under a scene light share: their arguments
and the plugin, a 300 x 300 GI view lit by one directional scene light above (no headlight),
its screenshots with GI off and on, the brightness of a box of pixels, and the end of the
test.
"""
import os
import sys

from paraview.simple import AddLight, CreateView, Delete, LoadPlugin, Render, SaveScreenshot

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from strict_image import mismatch, rgb  # noqa: E402

SIZE = 300


def start(argv):
    """The test's arguments PLUGIN BASELINE OUTPUT_DIR (the output folder made), the plugin
    loaded, and the view (create()): (view, baseline, output_dir)."""
    plugin, baseline, output_dir = [os.path.abspath(a) for a in argv[:3]]
    os.makedirs(output_dir, exist_ok=True)
    LoadPlugin(plugin, ns=globals())
    return create(), baseline, output_dir


def create():
    """The GI view (64^3 voxels), lit by one directional scene light from (10, 40, 20)."""
    view = CreateView("VoxelGIRenderView")
    view.ViewSize = [SIZE, SIZE]
    view.OrientationAxesVisibility = 0
    view.VoxelResolution = 64
    view.UseLight = 0  # no headlight: one scene light above casts the shadows
    light = AddLight(view=view)
    light.Coords = "Scene"
    light.Type = "Directional"
    light.Position = [10, 40, 20]
    light.FocalPoint = [0, 0, 0]
    return view


def screenshots(view, output_dir, name, failures):
    """The view's image with GI off (NAME-plain.png) and on (NAME.png); a failure when GI
    did not run."""
    paths = []
    for gi, suffix in ((0, "-plain"), (1, "")):
        view.EnableVoxelGI = gi
        Render(view)
        paths.append(os.path.join(output_dir, name + suffix + ".png"))
        SaveScreenshot(paths[-1], view, ImageResolution=[SIZE, SIZE])
    view.SMProxy.UpdatePropertyInformation()
    if not view.SMProxy.GetProperty("GIActive").GetElement(0):
        failures.append("GI did not run in the view")
    return paths


def mean(path, box):
    """Mean brightness of the pixels in box (x0, y0, x1, y1; y up, as VTK's rows)."""
    return rgb(path).reshape(SIZE, SIZE, 3)[box[1]:box[3], box[0]:box[2]].mean()


def finish(view, baseline, rendered, output_dir, failures):
    """Compare with the baseline, delete the view (ParaView 5.11's pvpython crashes in
    sys.exit() while views are alive: the caller drops its name too) and print the failures;
    the exit status."""
    problem = mismatch(baseline, rendered, output_dir)
    if problem:
        failures.append(problem)
    Delete(view)
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0
