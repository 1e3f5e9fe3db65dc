"""Writes the built-in Cornell box (vtkVoxelGIScenes) as a scene both renderers read:
OUT.obj + OUT.mtl (vtkOBJExporter: geometry and diffuse colours, one material per actor, in
actor order) and OUT.json (camera, lights, per-material emission, image size).

    python3 export_scene.py OUT_PREFIX          (build/lib/python3/dist-packages on PYTHONPATH)
"""
import json
import sys

from vtkmodules.vtkIOExport import vtkOBJExporter
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (render window factory)
from voxelgi import vtkVoxelGIPass, vtkVoxelGIScenes

prefix = sys.argv[1]
size = (200, 200)
renderer = vtkRenderer()
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(*size)
window.AddRenderer(renderer)
vtkVoxelGIScenes.AddCornellBox(renderer)
window.Render()

exporter = vtkOBJExporter()
exporter.SetRenderWindow(window)
exporter.SetFilePrefix(prefix)
exporter.Write()
with open(prefix + ".mtl") as f:
    materials = [line.split()[1] for line in f if line.startswith("newmtl")]

emission = {}
actors = renderer.GetActors()
for i in range(actors.GetNumberOfItems()):
    keys = actors.GetItemAsObject(i).GetPropertyKeys()
    key = vtkVoxelGIPass.EMISSION()
    if keys is not None and keys.Has(key):
        emission[materials[i]] = [key.Get(keys, c) for c in range(3)]

lights = []
for i in range(renderer.GetLights().GetNumberOfItems()):
    light = renderer.GetLights().GetItemAsObject(i)
    if not light.GetPositional() or light.GetConeAngle() < 90.0 or \
            light.GetAttenuationValues() != (1.0, 0.0, 0.0):
        sys.exit("only unattenuated point lights are described")
    lights.append({"type": "point", "position": list(light.GetPosition()),
                   "color": list(light.GetDiffuseColor()), "intensity": light.GetIntensity()})

camera = renderer.GetActiveCamera()
scene = {"obj": prefix.split("/")[-1] + ".obj", "size": list(size),
         "camera": {"position": list(camera.GetPosition()),
                    "focal_point": list(camera.GetFocalPoint()),
                    "view_up": list(camera.GetViewUp()), "view_angle": camera.GetViewAngle()},
         "lights": lights, "emission": emission}
with open(prefix + ".json", "w") as f:
    json.dump(scene, f, indent=2)
