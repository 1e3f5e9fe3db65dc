"""A scientific-visualization scene with voxel GI and ambient occlusion: isosurfaces of VTK's
wavelet source, coloured by elevation through a lookup table, standing in a simple room
(floor and two walls) lit by one positional light. Written to a PNG.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/wavelet_isosurface.py [output.png]

(from the repository root after the set-up; VTK's Python is Debian's /usr/bin/python3,
which may not be the python3 first on PATH)
"""
import sys

from vtkmodules.vtkFiltersCore import vtkContourFilter, vtkElevationFilter
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkWindowToImageFilter)

from voxelgi import vtkVoxelGIPass


def wall(renderer, origin, point1, point2):
    plane = vtkPlaneSource()
    plane.SetOrigin(origin)
    plane.SetPoint1(point1)
    plane.SetPoint2(point2)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(plane.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.85, 0.85, 0.8)
    renderer.AddActor(actor)


def main(output="wavelet_isosurface.png"):
    renderer = vtkRenderer()

    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-10, 10, -10, 10, -10, 10)
    contour = vtkContourFilter()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, 190.0)
    elevation = vtkElevationFilter()
    elevation.SetInputConnection(contour.GetOutputPort())
    elevation.SetLowPoint(0, -10, 0)
    elevation.SetHighPoint(0, 10, 0)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(elevation.GetOutputPort())
    mapper.SetScalarRange(0.0, 1.0)
    surface = vtkActor()
    surface.SetMapper(mapper)
    renderer.AddActor(surface)

    # floor under the isosurface and two walls behind it, normals toward the scene
    wall(renderer, (-16, -11, -16), (-16, -11, 16), (16, -11, -16))
    wall(renderer, (-16, -11, -12), (16, -11, -12), (-16, 16, -12))
    wall(renderer, (-13, -11, -16), (-13, 16, -16), (-13, -11, 16))

    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(True)
    light.SetConeAngle(90.0)
    light.SetPosition(8.0, 18.0, 14.0)
    light.SetFocalPoint(0.0, 0.0, 0.0)
    renderer.AddLight(light)

    camera = renderer.GetActiveCamera()
    camera.SetPosition(30.0, 14.0, 56.0)
    camera.SetFocalPoint(-1.0, -1.0, -2.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    renderer.ResetCameraClippingRange()

    window = vtkRenderWindow()
    window.SetSize(320, 240)
    window.SetOffScreenRendering(True)
    window.AddRenderer(renderer)

    gi = vtkVoxelGIPass()
    gi.SetVoxelResolution(64)
    gi.SetAmbientOcclusionStrength(0.8)
    renderer.SetPass(gi)
    window.Render()
    if not gi.GetGIActive():
        sys.exit("voxel GI could not run on this OpenGL context")

    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(output)
    writer.Write()


if __name__ == "__main__":
    main(*sys.argv[1:2])
