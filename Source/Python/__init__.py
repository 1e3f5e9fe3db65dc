"""VoxelGI for VTK: real-time voxel global illumination as a VTK render pass.

    from voxelgi import vtkVoxelGIPass
    gi = vtkVoxelGIPass()
    renderer.SetPass(gi)
"""
# VTK's OpenGL backend must be loaded before the pass is created.
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

from .vtkRenderingVoxelGI import *  # noqa: F401,F403
