"""The README's pvpython snippet, run verbatim by pvpython in a fresh directory that sees the
build's plugin at the README's relative path: its contour must have points (a contour without
ContourBy has none) and its screenshot must not be blank.

    pvpython test_readme_snippet.py README.md BUILD_PARAVIEW_DIR
"""
import os
import re
import sys
import tempfile

from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy

readme, build = [os.path.abspath(a) for a in sys.argv[1:3]]
with open(readme) as f:
    snippet = [s for s in re.findall(r"```python\n(.*?)```", f.read(), re.S)
               if s.startswith("from paraview.simple")]
if len(snippet) != 1:
    print("FAILED: expected one pvpython snippet, found %d" % len(snippet))
    sys.exit(1)
work = tempfile.mkdtemp()
os.symlink(build, os.path.join(work, "build-paraview"))
os.chdir(work)
exec(snippet[0], {})
from paraview.simple import GetSources  # noqa: E402
contours = [proxy for (name, _), proxy in GetSources().items() if name.startswith("Contour")]
points = contours[0].GetDataInformation().GetNumberOfPoints() if contours else 0
print("pvpython snippet: the contour has %d points" % points)
if points == 0:
    print("FAILED: the snippet's contour is empty")
    sys.exit(1)
shot = os.path.join(work, "voxelgi-paraview.png")
if not os.path.exists(shot):
    print("FAILED: the snippet saved no screenshot")
    sys.exit(1)
reader = vtkPNGReader()
reader.SetFileName(shot)
reader.Update()
pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())
print("pvpython snippet: screenshot %s, mean %.1f, deviation %.1f" % (
    reader.GetOutput().GetDimensions(), pixels.mean(), pixels.std()))
if pixels.std() < 10.0:
    print("FAILED: the screenshot is blank")
    sys.exit(1)
