"""An unmodified kind of vedo program with voxel GI: a mesh standing on a floor, with vedo's
axes, rendered by vedo's Plotter; the pass is set on the plotter's renderer. vedo's meshes
are vtkFollowers and its axes an assembly: the mesh and the floor are voxelized (shadows,
colour bleeding), the axes are drawn by VTK. Written to a PNG; exits with an error when GI
did not run or a frame that changes nothing traced again.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/vedo_mesh.py [output.png]

(needs Debian's python3-vedo, which the set-up installs)
"""
import sys

import vedo

from voxelgi import vtkVoxelGIPass


def stages(gi):
    return ",".join(vtkVoxelGIPass.GetStageName(s) for s in range(vtkVoxelGIPass.NUMBER_OF_STAGES)
                    if gi.GetStageRan(s))


def main(output="vedo_mesh.png"):
    vedo.settings.default_backend = "vtk"
    mesh = vedo.Sphere(r=0.5, res=48)
    mesh.pos(0, 0.5, 0).color("tomato")
    floor = vedo.Box(pos=(0, -0.05, 0), length=3, width=0.1, height=3).color("lightgray")
    plotter = vedo.Plotter(offscreen=True, size=(300, 300))
    plotter.show(mesh, floor, axes=1, interactive=False,
                 camera={"pos": (2.5, 2.5, 4.0), "focal_point": (0, 0.3, 0), "viewup": (0, 1, 0)})
    gi = vtkVoxelGIPass()
    plotter.renderer.SetPass(gi)
    plotter.render()
    if not gi.GetGIActive():
        sys.exit("GI did not run")
    plotter.render()
    if stages(gi) != "Scan,Present":
        sys.exit("an unchanged frame ran " + stages(gi))
    plotter.screenshot(output)
    plotter.close()


if __name__ == "__main__":
    main(*sys.argv[1:])
