"""A volume among surfaces, as a sci-vis program draws it: VTK's wavelet volume-rendered (GPU
ray casting through colour and opacity transfer functions) over a floor, beside an isosurface
of the same data and stream tubes, lit by one scene light. With voxel GI the volume casts a
soft shadow on the floor and darkens what stands near it, and VTK's drawing of the volume adds
the light the scene sends it.
Writes the image with GI and, given a second name, plain VTK's image of the same scene.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/volume_scene.py [gi.png [plain.png]]

(from the repository root after the set-up; VTK's Python is Debian's /usr/bin/python3)
"""
import math
import sys

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPiecewiseFunction, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkContourFilter, vtkTubeFilter
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkLight,
                                         vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkVolume, vtkVolumeProperty, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401 (the GPU volume mapper's factory)
from vtkmodules.vtkRenderingVolume import vtkGPUVolumeRayCastMapper

from voxelgi import vtkVoxelGIPass


def actor_of(algorithm_or_data, color):
    mapper = vtkPolyDataMapper()
    if isinstance(algorithm_or_data, vtkPolyData):
        mapper.SetInputData(algorithm_or_data)
    else:
        mapper.SetInputConnection(algorithm_or_data.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(color)
    return actor


def scene():
    renderer = vtkRenderer()
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-10, 10, -10, 10, -10, 10)

    # the volume: the wavelet's high values, orange to white
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(120.0, 0.0)
    opacity.AddPoint(190.0, 0.15)
    opacity.AddPoint(280.0, 0.6)
    color = vtkColorTransferFunction()
    color.AddRGBPoint(120.0, 0.8, 0.3, 0.1)
    color.AddRGBPoint(280.0, 1.0, 0.95, 0.8)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(color)
    prop.SetScalarOpacityUnitDistance(2.0)
    prop.SetInterpolationTypeToLinear()
    mapper = vtkGPUVolumeRayCastMapper()
    mapper.SetInputConnection(wavelet.GetOutputPort())
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer.AddVolume(volume)

    # an isosurface of the same data beside it
    contour = vtkContourFilter()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, 200.0)
    iso = actor_of(contour, (0.3, 0.5, 0.9))
    iso.SetPosition(28.0, 0.0, -2.0)
    renderer.AddActor(iso)

    # stream tubes: three lines sweeping over the floor behind the two, as tube triangles
    points = vtkPoints()
    lines = vtkCellArray()
    for k in range(3):
        lines.InsertNextCell(100)
        for i in range(100):
            t = i / 99.0
            points.InsertNextPoint(-20.0 + 60.0 * t, -7.0 + 5.0 * k + 3.0 * math.sin(6.0 * t + k),
                                   -20.0 + 4.0 * math.sin(3.0 * t + k))
            lines.InsertCellPoint(k * 100 + i)
    streams = vtkPolyData()
    streams.SetPoints(points)
    streams.SetLines(lines)
    tubes = vtkTubeFilter()
    tubes.SetInputData(streams)
    tubes.SetRadius(0.8)
    tubes.SetNumberOfSides(12)
    renderer.AddActor(actor_of(tubes, (0.9, 0.85, 0.3)))

    floor = vtkPlaneSource()
    floor.SetOrigin(-30.0, -11.0, -30.0)
    floor.SetPoint1(-30.0, -11.0, 25.0)
    floor.SetPoint2(50.0, -11.0, -30.0)
    renderer.AddActor(actor_of(floor, (0.85, 0.85, 0.8)))

    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(False)
    light.SetPosition(-25.0, 40.0, 20.0)
    light.SetFocalPoint(0.0, 0.0, 0.0)
    renderer.AddLight(light)

    camera = renderer.GetActiveCamera()
    camera.SetPosition(30.0, 45.0, 85.0)
    camera.SetFocalPoint(10.0, -6.0, -4.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    renderer.ResetCameraClippingRange()
    return renderer


def write(window, name):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(name)
    writer.Write()


def main(output="volume_scene.png", plain_output=None):
    renderer = scene()
    window = vtkRenderWindow()
    window.SetSize(480, 320)
    window.SetOffScreenRendering(True)
    window.AddRenderer(renderer)
    gi = vtkVoxelGIPass()
    gi.SetVoxelResolution(128)
    renderer.SetPass(gi)
    window.Render()
    if not gi.GetGIActive():
        sys.exit("voxel GI could not run on this OpenGL context")
    write(window, output)
    if plain_output:
        renderer.SetPass(None)
        window.Render()
        write(window, plain_output)


if __name__ == "__main__":
    main(*sys.argv[1:3])
