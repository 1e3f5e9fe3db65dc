"""Renders a scene written by export_scene.py with Blender Cycles: the path-traced reference.

    blender -b -P render_cycles.py -- SCENE.json OUT_PREFIX SAMPLES SEED

Writes OUT_PREFIX.pfm (linear float RGB, rows bottom to top) and OUT_PREFIX.png (preview).

How VTK's model maps to Cycles (VTK shading is Lambert without 1/pi, lights do not fall off):
- material Kd (VTK diffuse colour x diffuse) -> Diffuse BSDF of that colour;
- vtkVoxelGIPass::EMISSION (r, g, b) -> Emission shader, colour (r, g, b) / max, strength max:
  its radiance is the emission, as the pass treats it;
- unattenuated VTK point light of intensity I -> point light of radius 0, power 4 pi^2 I, with
  the Light Falloff node's constant output: irradiance pi I cos(theta) at every distance, so a
  surface of albedo rho reflects rho I cos(theta), VTK's value. (A direct-light-only render of
  the Cornell box matches VTK's own image to within 1 %: median ratio 39.50 against
  4 pi^2 = 39.48.)
"""
import json
import math
import os
import struct
import sys

import bpy
from mathutils import Matrix, Vector

scene_path, prefix, samples, seed = sys.argv[sys.argv.index("--") + 1:][:4]
with open(scene_path) as f:
    desc = json.load(f)

bpy.ops.wm.read_factory_settings(use_empty=True)
# no axis conversion: Blender sees VTK's coordinates
bpy.ops.wm.obj_import(filepath=os.path.join(os.path.dirname(scene_path), desc["obj"]),
                      forward_axis='Y', up_axis='Z')
for obj in bpy.context.scene.objects:
    for slot in obj.material_slots:
        material = slot.material
        nodes = material.node_tree.nodes
        kd = nodes["Principled BSDF"].inputs["Base Color"].default_value[:3]
        nodes.clear()
        output = nodes.new("ShaderNodeOutputMaterial")
        emission = desc["emission"].get(material.name)
        if emission:
            strength = max(emission)
            shader = nodes.new("ShaderNodeEmission")
            shader.inputs["Color"].default_value = (*[c / strength for c in emission], 1.0)
            shader.inputs["Strength"].default_value = strength
        else:
            shader = nodes.new("ShaderNodeBsdfDiffuse")
            shader.inputs["Color"].default_value = (*kd, 1.0)
        material.node_tree.links.new(shader.outputs[0], output.inputs["Surface"])

scene = bpy.context.scene
for i, light in enumerate(desc["lights"]):
    data = bpy.data.lights.new("light%d" % i, "POINT")
    data.energy = 4.0 * math.pi ** 2 * light["intensity"]
    data.shadow_soft_size = 0.0
    data.color = light["color"]
    data.use_nodes = True
    falloff = data.node_tree.nodes.new("ShaderNodeLightFalloff")
    falloff.inputs["Strength"].default_value = 1.0  # the light's power scales it
    data.node_tree.links.new(falloff.outputs["Constant"],
                             data.node_tree.nodes["Emission"].inputs["Strength"])
    obj = bpy.data.objects.new("light%d" % i, data)
    obj.location = light["position"]
    scene.collection.objects.link(obj)

cam = desc["camera"]
data = bpy.data.cameras.new("camera")
data.sensor_fit = 'VERTICAL'
data.angle_y = math.radians(cam["view_angle"])
camera = bpy.data.objects.new("camera", data)
camera.location = cam["position"]
# Blender cameras look down their -Z with +Y up: build that frame from VTK's camera.
back = (Vector(cam["position"]) - Vector(cam["focal_point"])).normalized()
right = Vector(cam["view_up"]).cross(back).normalized()
camera.rotation_euler = Matrix((right, back.cross(right), back)).transposed().to_euler()
scene.collection.objects.link(camera)
scene.camera = camera

scene.world = bpy.data.worlds.new("black")
scene.world.color = (0.0, 0.0, 0.0)
scene.render.engine = 'CYCLES'
scene.cycles.device = 'CPU'
scene.cycles.samples = int(samples)
scene.cycles.seed = int(seed)
scene.cycles.use_adaptive_sampling = False
scene.cycles.use_denoising = False
scene.cycles.max_bounces = 8
scene.cycles.diffuse_bounces = 8
scene.cycles.sample_clamp_direct = 0.0
scene.cycles.sample_clamp_indirect = 0.0
scene.render.resolution_x, scene.render.resolution_y = desc["size"]
scene.render.resolution_percentage = 100
scene.view_settings.view_transform = 'Standard'
scene.render.image_settings.file_format = 'OPEN_EXR'
scene.render.image_settings.color_depth = '32'
scene.render.filepath = prefix + ".exr"
bpy.ops.render.render(write_still=True)

image = bpy.data.images.load(prefix + ".exr")
w, h = image.size
pixels = image.pixels[:]
with open(prefix + ".pfm", "wb") as f:
    f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
    f.write(struct.pack("<%df" % (w * h * 3),
                        *[pixels[4 * i + c] for i in range(w * h) for c in range(3)]))
scene.render.image_settings.file_format = 'PNG'
scene.render.image_settings.color_depth = '8'
image.save_render(prefix + ".png", scene=scene)
os.remove(prefix + ".exr")
