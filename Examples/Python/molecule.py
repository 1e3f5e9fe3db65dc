"""A molecule as a chemistry program draws it: VTK's vtkMoleculeMapper in its ball-and-stick
look (atoms of a third of their van der Waals radii, bonds as sticks, both in the periodic
table's colours), here a phenol ring standing over a floor beside a cloud of sphere splats
(a vtkPointGaussianMapper with ParaView's sphere shape), under one scene light. VTK draws both
as shaded sprites without triangles; with voxel GI they are voxelized as the spheres and sticks
they show, so they cast shadows, darken the floor around them and bleed their colours onto it.
Writes the image with GI and, given a second name, plain VTK's image of the same scene.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/molecule.py [gi.png [plain.png]]

(from the repository root after the set-up; VTK's Python is Debian's /usr/bin/python3)
"""
import math
import sys

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkMolecule, vtkPolyData
from vtkmodules.vtkDomainsChemistry import vtkMoleculeMapper
import vtkmodules.vtkDomainsChemistryOpenGL2  # noqa: F401 (the molecule mapper's factory)
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPointGaussianMapper,
                                         vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)

from voxelgi import vtkVoxelGIPass

SPHERE_SPLAT = ("//VTK::Color::Impl\n"
                "float dist = dot(offsetVCVSOutput.xy, offsetVCVSOutput.xy);\n"
                "if (dist > 1.0) { discard; }\n")


def phenol():
    """A benzene ring (bonds alternating single and double) with five hydrogens and an OH."""
    molecule = vtkMolecule()
    ring = []
    for i in range(6):
        a = 2.0 * math.pi * i / 6.0
        ring.append(molecule.AppendAtom(6, 1.4 * math.cos(a), 2.2 + 1.4 * math.sin(a), 0.0))
    for i in range(6):
        molecule.AppendBond(ring[i], ring[(i + 1) % 6], 2 if i % 2 else 1)
        a = 2.0 * math.pi * i / 6.0
        element, reach = (8, 2.8) if i == 0 else (1, 2.5)
        outer = molecule.AppendAtom(element, reach * math.cos(a), 2.2 + reach * math.sin(a), 0.0)
        molecule.AppendBond(ring[i], outer, 1)
        if element == 8:
            molecule.AppendBond(outer, molecule.AppendAtom(1, 3.4, 2.9, 0.0), 1)
    return molecule


def cloud():
    """60 points filling a ball of radius 1.2 evenly (a spiral, so every run draws the same)."""
    points = vtkPoints()
    vertices = vtkCellArray()
    for i in range(60):
        r = 1.2 * ((i * 0.7548777 + 0.5) % 1.0) ** (1.0 / 3.0)
        z = 1.0 - 2.0 * (i + 0.5) / 60.0
        a = i * 2.39996
        s = math.sqrt(1.0 - z * z)
        vertices.InsertNextCell(1)
        vertices.InsertCellPoint(points.InsertNextPoint(
            -3.6 + r * s * math.cos(a), 1.4 + r * z, 1.0 + r * s * math.sin(a)))
    data = vtkPolyData()
    data.SetPoints(points)
    data.SetVerts(vertices)
    return data


def scene():
    renderer = vtkRenderer()
    renderer.SetBackground(0.1, 0.1, 0.12)
    renderer.AutomaticLightCreationOff()

    atoms = vtkMoleculeMapper()
    atoms.SetInputData(phenol())
    atoms.UseBallAndStickSettings()
    molecule = vtkActor()
    molecule.SetMapper(atoms)
    renderer.AddActor(molecule)

    splats = vtkPointGaussianMapper()
    splats.SetInputData(cloud())
    splats.SetSplatShaderCode(SPHERE_SPLAT)
    splats.SetScaleFactor(0.25)
    splats.EmissiveOff()
    particles = vtkActor()
    particles.SetMapper(splats)
    particles.GetProperty().SetColor(0.3, 0.55, 0.95)
    renderer.AddActor(particles)

    floor = vtkPlaneSource()
    floor.SetOrigin(-9.0, 0.0, -6.0)
    floor.SetPoint1(7.0, 0.0, -6.0)
    floor.SetPoint2(-9.0, 0.0, 6.0)
    ground = vtkPolyDataMapper()
    ground.SetInputConnection(floor.GetOutputPort())
    plane = vtkActor()
    plane.SetMapper(ground)
    plane.GetProperty().SetColor(0.85, 0.85, 0.8)
    renderer.AddActor(plane)

    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(False)
    light.SetPosition(2.0, 10.0, 4.0)
    light.SetFocalPoint(0.0, 0.0, 0.0)
    renderer.AddLight(light)

    camera = renderer.GetActiveCamera()
    camera.SetPosition(-0.5, 7.0, 13.0)
    camera.SetFocalPoint(-0.5, 1.6, 0.0)
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


def main(output="molecule.png", plain_output=None):
    renderer = scene()
    window = vtkRenderWindow()
    window.SetSize(480, 320)
    window.SetOffScreenRendering(True)
    window.AddRenderer(renderer)
    gi = vtkVoxelGIPass()
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
