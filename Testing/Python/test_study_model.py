"""Examples/Python/study_model.py writes a scene description that reads back: the model and its
floor as two actors, VTK's automatic headlight as one directional light along the view, and
the note that says so.

    python3 test_study_model.py EXAMPLE OUT_DIR
"""
import json
import os
import subprocess
import sys

from vtkmodules.vtkRenderingCore import vtkRenderer
from voxelgi import vtkVoxelGISceneFile

example, out = sys.argv[1:3]
os.makedirs(out, exist_ok=True)
path = os.path.join(out, "study_model.json")
notes = subprocess.run([sys.executable, example, path], check=True, capture_output=True,
                       text=True).stdout
assert notes == "the headlight is written as a scene light for the current camera\n", notes
with open(path) as f:
    scene = json.load(f)
camera = scene["camera"]
view = [f - p for f, p in zip(camera["focal_point"], camera["position"])]
norm = sum(v * v for v in view) ** 0.5
lights = scene["lights"]
assert len(lights) == 1 and lights[0]["type"] == "directional", lights
assert all(abs(d - v / norm) < 1e-6 for d, v in zip(lights[0]["direction"], view)), lights
assert scene["size"] == [300, 300], scene["size"]

renderer = vtkRenderer()
description = vtkVoxelGISceneFile()
description.SetFileName(path)
assert description.Read(renderer)
assert renderer.GetActors().GetNumberOfItems() == 2
assert renderer.GetLights().GetNumberOfItems() == 1
print("study_model: 2 actors and the headlight as a directional light read back")
