"""Headless rendering from Python through EGL with the GLEW shim preloaded, as the README says
to run it: the child process must exit cleanly (the shim once crashed there: Python loads
GLEW with RTLD_LOCAL, out of RTLD_NEXT's reach), GLEW must not be reported as failing, and GI
must run and give a finite, lit image.

Usage: test_egl_shim.py SHIM_LIBRARY   (PYTHONPATH holds the voxelgi package)
"""
import os
import subprocess
import sys

CHILD = r"""
import math
from voxelgi import vtkVoxelGIPass, vtkVoxelGIScenes, vtkVoxelGIEGLRenderWindow
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkRenderingCore import vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
renderer = vtkRenderer()
vtkVoxelGIScenes.AddCornellBox(renderer)
window = vtkVoxelGIEGLRenderWindow()
window.SetSize(64, 64)
window.AddRenderer(renderer)
gi = vtkVoxelGIPass()
gi.SetVoxelResolution(16)
renderer.SetPass(gi)
window.Render()
window.Render()
pixels = vtkFloatArray()
assert gi.GetGIActive(), "GI did not run"
assert gi.GetFloatImage(vtkVoxelGIPass.IMAGE_COMPOSITE, pixels), "no composite image"
values = [pixels.GetValue(i) for i in range(pixels.GetNumberOfValues())]
assert all(math.isfinite(v) for v in values), "non-finite pixels"
mean = sum(values) / len(values)
print("mean composite value %.4f" % mean)
assert mean > 0.01, "the image is black"
"""


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    env = dict(os.environ, LD_PRELOAD=sys.argv[1], EGL_PLATFORM="surfaceless")
    env.pop("DISPLAY", None)
    child = subprocess.run([sys.executable, "-c", CHILD], env=env, capture_output=True,
                           text=True, timeout=240)
    print(child.stdout, end="")
    print(child.stderr[-4000:], end="", file=sys.stderr)
    if child.returncode != 0:
        print("FAILED: the EGL render exited with %d" % child.returncode)
        return 1
    if "GLEW could not be initialized" in child.stderr:
        print("FAILED: VTK reported that GLEW could not be initialized")
        return 1
    print("passed: clean exit, GLEW initialized, GI image lit")
    return 0


if __name__ == "__main__":
    sys.exit(main())
