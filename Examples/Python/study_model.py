"""Error against run time for a model of your own: shows a model file as a VTK program would (on
a floor, lit by VTK's automatic headlight) and writes that renderer's scene description, which
Testing/Reference/study_scene.sh then renders with Cycles and studies in one command:

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/study_model.py \\
        [MODEL.ply|.stl|.obj|.vtp] out/model.json
    Testing/Reference/study_scene.sh out/model.json out/

Any program does the same with its own renderer:

    description = vtkVoxelGISceneFile()
    description.SetFileName("out/scene.json")
    if not description.Write(renderer):
        print(description.GetProblems())   # what Cycles cannot match, one use per line

Without MODEL, a torus knot stands in.
"""
import sys

from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkParametricFunctionSource
from vtkmodules.vtkCommonComputationalGeometry import vtkParametricTorus
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer

from voxelgi import vtkVoxelGISceneFile


def model_source(path):
    if path is None:
        torus = vtkParametricTorus()
        torus.SetRingRadius(1.0)
        torus.SetCrossSectionRadius(0.35)
        source = vtkParametricFunctionSource()
        source.SetParametricFunction(torus)
        return source
    readers = {".ply": vtkPLYReader, ".stl": vtkSTLReader, ".obj": vtkOBJReader,
               ".vtp": vtkXMLPolyDataReader}
    reader = readers[path[path.rfind("."):].lower()]()
    reader.SetFileName(path)
    return reader


def main(model, out):
    source = model_source(model)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(source.GetOutputPort())
    normals.Update()
    bounds = normals.GetOutput().GetBounds()
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    renderer = vtkRenderer()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.9, 0.55, 0.3)
    renderer.AddActor(actor)

    # a floor under the model: y is up, as in most model files
    floor = vtkCubeSource()
    floor.SetBounds(bounds[0] - size, bounds[1] + size, bounds[2] - 0.05 * size, bounds[2],
                    bounds[4] - size, bounds[5] + size)
    floor_mapper = vtkPolyDataMapper()
    floor_mapper.SetInputConnection(floor.GetOutputPort())
    floor_actor = vtkActor()
    floor_actor.SetMapper(floor_mapper)
    floor_actor.GetProperty().SetColor(0.8, 0.8, 0.8)
    renderer.AddActor(floor_actor)

    camera = renderer.GetActiveCamera()
    center = [(bounds[2 * i] + bounds[2 * i + 1]) / 2 for i in range(3)]
    camera.SetFocalPoint(center)
    camera.SetPosition(center[0] + 0.9 * size, center[1] + 0.7 * size, center[2] + 1.6 * size)
    renderer.ResetCameraClippingRange()

    description = vtkVoxelGISceneFile()
    description.SetFileName(out)
    description.SetSize(300, 300)
    if not description.Write(renderer):
        sys.exit(description.GetProblems())
    sys.stdout.write(description.GetNotes())


if __name__ == "__main__":
    args = sys.argv[1:]
    main(args[0] if len(args) > 1 else None, args[-1])
