"""The built-in Cornell box with voxel global illumination, written to a PNG.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/cornell_box.py [output.png]

(from the repository root after the set-up; VTK's Python is Debian's /usr/bin/python3,
which may not be the python3 first on PATH)
"""
import sys

from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter

from voxelgi import vtkVoxelGIPass, vtkVoxelGIScenes


def write_png(window, path):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(path)
    writer.Write()


def main(output="cornell_box.png"):
    renderer = vtkRenderer()
    vtkVoxelGIScenes.AddCornellBox(renderer)
    window = vtkRenderWindow()
    window.SetSize(300, 300)
    window.SetOffScreenRendering(True)
    window.AddRenderer(renderer)

    gi = vtkVoxelGIPass()
    gi.SetVoxelResolution(64)
    renderer.SetPass(gi)
    window.Render()
    if not gi.GetGIActive():
        sys.exit("voxel GI could not run on this OpenGL context")
    write_png(window, output)


if __name__ == "__main__":
    main(*sys.argv[1:2])
