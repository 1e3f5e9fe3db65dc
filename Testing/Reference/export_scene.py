"""Writes one of the built-in scenes (vtkVoxelGIScenes.AddScene) as a description both renderers
read: OUT.obj + OUT.mtl (vtkOBJExporter: geometry and normals, one material per actor, in actor
order; scalar colours added as OBJ vertex colours) and OUT.json (camera, lights, background,
and per material the diffuse, specular and emission terms of VTK's model, image size).

    python3 export_scene.py SCENE OUT_PREFIX     (build/lib/python3/dist-packages on PYTHONPATH)

SCENE: cornell, glossy, isosurface, glyphs, emissive or streamlines. Stops with a message when the scene uses VTK
features that have no counterpart in the description (attenuated or spot lights, headlights,
an ambient term that is not the background's sky light).
"""
import json
import math
import sys

from vtkmodules.vtkIOExport import vtkOBJExporter
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (render window factory)
from voxelgi import vtkVoxelGIPass, vtkVoxelGIScenes

from float_images import srgb_encode

scene_name, prefix = sys.argv[1:3]
size = (200, 200)
renderer = vtkRenderer()
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(*size)
window.AddRenderer(renderer)
if not vtkVoxelGIScenes.AddScene(renderer, scene_name):
    sys.exit("unknown scene " + scene_name)
window.Render()

exporter = vtkOBJExporter()
exporter.SetRenderWindow(window)
exporter.SetFilePrefix(prefix)
exporter.Write()
with open(prefix + ".mtl") as f:
    names = [line.split()[1] for line in f if line.startswith("newmtl")]


def scaled(k, color):
    return [k * c for c in color]


def close(a, b):
    return all(abs(x - y) < 1e-6 for x, y in zip(a, b))


background = list(renderer.GetBackground())
actors = renderer.GetActors()
if actors.GetNumberOfItems() != len(names):
    sys.exit("every actor must become one material")
materials = {}
vertex_colors = {}
for i in range(actors.GetNumberOfItems()):
    actor = actors.GetItemAsObject(i)
    prop = actor.GetProperty()
    material = {"diffuse": scaled(prop.GetDiffuse(), prop.GetDiffuseColor()),
                "specular": scaled(prop.GetSpecular(), prop.GetSpecularColor()),
                "specular_power": prop.GetSpecularPower()}
    keys = actor.GetPropertyKeys()
    if keys is not None and keys.Has(vtkVoxelGIPass.EMISSION()):
        material["emission"] = [vtkVoxelGIPass.EMISSION().Get(keys, c) for c in range(3)]
    mapper = actor.GetMapper()
    colors = mapper.MapScalars(1.0) if mapper.GetScalarVisibility() else None
    if colors is not None and colors.GetNumberOfTuples() > 0:
        if colors.GetNumberOfTuples() != mapper.GetInput().GetNumberOfPoints() or \
                prop.GetAmbient() > 0.0:
            sys.exit("scalar colours: point scalars on a surface without ambient term only")
        vertex_colors[i] = colors
        material["vertex_colors"] = True
    elif "emission" not in material:
        # VTK's ambient term only has a physical counterpart as the sky light of the
        # background, reflected by the diffuse colour: Ka Ca = background Kd.
        ambient = scaled(prop.GetAmbient(), prop.GetAmbientColor())
        if not close(ambient, [b * d for b, d in zip(background, material["diffuse"])]):
            sys.exit("%s: ambient term %s is not the background's sky light" % (names[i], ambient))
    materials[names[i]] = material

# Texture coordinates go: the exporter numbers them like the points even where an actor has
# none, which makes the importer drop faces, and nothing here is textured. Scalar colours
# become vertex colours (each actor's points come before its "g" line); the importer keeps
# them only if every vertex has one, so the other actors' vertices get white, which their
# materials do not read.
with open(prefix + ".obj") as f:
    lines = f.read().split("\n")
out = []
actor, point = 0, 0
for line in lines:
    if line.startswith("vt "):
        continue
    if line.startswith("g "):
        actor, point = actor + 1, 0
    elif line.startswith("v ") and vertex_colors:
        rgb = vertex_colors[actor].GetTuple(point)[:3] if actor in vertex_colors else (255,) * 3
        # Blender's OBJ importer reads vertex colours as sRGB: encode VTK's linear values.
        line += " " + " ".join("%.6f" % srgb_encode(c / 255.0) for c in rgb)
        point += 1
    elif line.startswith("f "):
        line = "f " + " ".join("%s//%s" % (v.split("/")[0], v.split("/")[-1])
                               for v in line.split()[1:])
    out.append(line)
with open(prefix + ".obj", "w") as f:
    f.write("\n".join(out))

lights = []
for i in range(renderer.GetLights().GetNumberOfItems()):
    light = renderer.GetLights().GetItemAsObject(i)
    if not light.LightTypeIsSceneLight():
        sys.exit("only scene lights are described")
    color = list(light.GetDiffuseColor())
    if not light.GetPositional():
        d = [f - p for f, p in zip(light.GetFocalPoint(), light.GetPosition())]
        length = math.sqrt(sum(c * c for c in d))
        lights.append({"type": "directional", "direction": [c / length for c in d],
                       "color": color, "intensity": light.GetIntensity()})
    elif light.GetConeAngle() >= 90.0 and light.GetAttenuationValues() == (1.0, 0.0, 0.0):
        lights.append({"type": "point", "position": list(light.GetPosition()),
                       "color": color, "intensity": light.GetIntensity()})
    else:
        sys.exit("only unattenuated point lights and directional lights are described")

camera = renderer.GetActiveCamera()
scene = {"obj": prefix.split("/")[-1] + ".obj", "size": list(size),
         "camera": {"position": list(camera.GetPosition()),
                    "focal_point": list(camera.GetFocalPoint()),
                    "view_up": list(camera.GetViewUp()), "view_angle": camera.GetViewAngle()},
         "background": background, "lights": lights, "materials": materials}
with open(prefix + ".json", "w") as f:
    json.dump(scene, f, indent=2)
