"""VoxelGI for VTK: real-time voxel global illumination as a VTK render pass.

    from voxelgi import vtkVoxelGIPass
    gi = vtkVoxelGIPass()
    renderer.SetPass(gi)

vtkVoxelGIScenes (the built-in scenes of the tests and examples) and vtkVoxelGIEGLRenderWindow
(a headless window through EGL) come from the helper module vtkTestingVoxelGI, which the render
pass does not need.
"""
# VTK's OpenGL backend must be loaded before the pass is created.
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

from .vtkRenderingVoxelGI import *  # noqa: F401,F403
from .vtkTestingVoxelGI import *  # noqa: F401,F403
