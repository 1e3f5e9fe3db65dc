"""Writes one of the built-in scenes (vtkVoxelGIScenes.AddScene) as the description both
renderers read (vtkVoxelGISceneFile): OUT.json, OUT.obj and OUT.mtl, at 200 x 200 pixels.

    python3 export_scene.py SCENE OUT_PREFIX     (build/lib/python3/dist-packages on PYTHONPATH)

SCENE: a name vtkVoxelGIScenes.AddScene knows (cornell, glossy, ..., contactsheadlight). A scene of your own:
vtkVoxelGISceneFile.Write(renderer) in your program, then study_scene.sh.
"""
import sys

from vtkmodules.vtkRenderingCore import vtkRenderer
from voxelgi import vtkVoxelGISceneFile, vtkVoxelGIScenes

scene_name, prefix = sys.argv[1:3]
renderer = vtkRenderer()
if not vtkVoxelGIScenes.AddScene(renderer, scene_name):
    sys.exit("unknown scene " + scene_name)
description = vtkVoxelGISceneFile()
description.SetFileName(prefix + ".json")
description.SetSize(200, 200)
if not description.Write(renderer):
    sys.exit(description.GetProblems())
sys.stdout.write(description.GetNotes())
