"""A Mayavi mlab program with voxel GI: a surface of z = exp(-(x^2 + y^2)) coloured by height,
rendered by mlab offscreen; the pass is set on the figure's VTK renderer (tvtk.to_vtk). The
surface is voxelized (its base darkens by ambient occlusion, its colours light each other).
Written to a PNG; exits with an error when GI did not run or a frame that changes nothing
traced again.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/mayavi_surface.py [output.png]

(needs Debian's mayavi2, which the set-up installs)
"""
import sys

import numpy as np
from mayavi import mlab
from tvtk.api import tvtk

from voxelgi import vtkVoxelGIPass


def stages(gi):
    return ",".join(vtkVoxelGIPass.GetStageName(s) for s in range(vtkVoxelGIPass.NUMBER_OF_STAGES)
                    if gi.GetStageRan(s))


def main(output="mayavi_surface.png"):
    mlab.options.offscreen = True
    figure = mlab.figure(size=(300, 300), bgcolor=(0.2, 0.2, 0.25))
    x, y = np.mgrid[-2:2:60j, -2:2:60j]
    mlab.surf(x, y, np.exp(-(x**2 + y**2)), colormap="viridis")
    mlab.view(azimuth=45, elevation=60, distance=8)
    gi = vtkVoxelGIPass()
    tvtk.to_vtk(figure.scene.renderer).SetPass(gi)
    figure.scene.render()
    if not gi.GetGIActive():
        sys.exit("GI did not run")
    figure.scene.render()
    if stages(gi) != "Scan,Present":
        sys.exit("an unchanged frame ran " + stages(gi))
    mlab.savefig(output)
    mlab.close(figure)


if __name__ == "__main__":
    main(*sys.argv[1:])
