"""The README's Python snippets run verbatim (under Xvfb, the module on PYTHONPATH) and give a
non-empty result: the first renders the Cornell box with GI (GI active, an image that is not
blank); the scene-description snippet, given that renderer as the `renderer` of "any renderer
your program built", writes out/scene.json, .obj and .mtl. pvpython snippets are the ParaView
build's test (Testing/ParaView/test_readme_snippet.py).

    test_readme_snippets.py README.md
"""
import os
import re
import sys
import tempfile


def snippets(readme):
    with open(readme) as f:
        return re.findall(r"```python\n(.*?)```", f.read(), re.S)


def main(readme):
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
    from vtkmodules.util.numpy_support import vtk_to_numpy

    found = [s for s in snippets(readme) if not s.startswith("from paraview")]
    render = [s for s in found if "vtkVoxelGIPass()" in s]
    describe = [s for s in found if "vtkVoxelGISceneFile()" in s]
    failures = []
    if len(render) != 1 or len(describe) != 1 or len(found) != 2:
        failures.append("expected the render and the description snippet, found %d snippets" % len(found))
        return failures
    names = {}
    exec(render[0], names)
    grab = vtkWindowToImageFilter()
    grab.SetInput(names["w"])
    grab.Update()
    pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    print("render snippet: GI active %d, image mean %.1f, deviation %.1f" % (
        names["gi"].GetGIActive(), pixels.mean(), pixels.std()))
    if not names["gi"].GetGIActive():
        failures.append("the render snippet ran without GI")
    if pixels.std() < 10.0:
        failures.append("the render snippet's image is blank")
    with tempfile.TemporaryDirectory() as out:
        os.chdir(out)
        os.mkdir("out")
        exec(describe[0], {"renderer": names["r"]})
        written = {n: os.path.getsize(os.path.join("out", n)) for n in os.listdir("out")}
        print("description snippet wrote", written)
        for name in ("scene.json", "scene.obj", "scene.mtl"):
            if written.get(name, 0) == 0:
                failures.append("the description snippet wrote no " + name)
        os.chdir("/")
    names["gi"].ReleaseGraphicsResources(names["w"])
    return failures


if __name__ == "__main__":
    problems = main(sys.argv[1])
    for p in problems:
        print("FAILED:", p)
    sys.exit(1 if problems else 0)
