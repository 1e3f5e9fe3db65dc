"""Renders a scene written by export_scene.py with Blender Cycles: the path-traced reference.

    blender -b -P render_cycles.py -- SCENE.json OUT_PREFIX SAMPLES SEED [BOUNCES]

Writes OUT_PREFIX.pfm (linear float RGB, rows bottom to top) and OUT_PREFIX.png (preview).
BOUNCES (default 8) caps the path's bounces: 0 gives the direct light alone, 1 the direct
light and one bounce, so the pass can be compared order by order (TestGIReference).

How VTK's model maps to Cycles (VTK shading is Lambert without 1/pi plus an unnormalized
Blinn-Phong highlight, and its lights do not fall off):
- diffuse term (diffuse coefficient x diffuse colour, or x the scalar colours, which arrive
  as the OBJ's vertex colours) -> Diffuse BSDF of that colour;
- specular term ks (specular coefficient x specular colour) of power n -> Glossy BSDF
  (Beckmann) of colour ks 8 / (n + 8) and roughness (2 / (n + 2))^(1/4), i.e. Beckmann alpha
  sqrt(2 / (n + 2)) (Walter et al. 2007), added to the diffuse one. VTK's highlight is not
  normalized (peak ks I whatever n): its lobe reflects about ks 8 / (n + 8) of the light, and
  a Beckmann lobe of that colour has VTK's peak, ks (n + 2) / (n + 8) I. The pass's specular
  cone (half-angle tan sqrt(2 / (n + 2))) carries the same share;
- vtkVoxelGIPass::EMISSION (r, g, b) -> Emission shader, colour (r, g, b) / max, strength max:
  its radiance is the emission, as the pass treats it;
- unattenuated VTK point light of intensity I -> point light of radius 0, power 4 pi^2 I, with
  the Light Falloff node's constant output: irradiance pi I cos(theta) at every distance, so a
  surface of albedo rho reflects rho I cos(theta), VTK's value. (A direct-light-only render of
  the Cornell box matches VTK's own image to within 1 %: median ratio 39.50 against
  4 pi^2 = 39.48.) A point light of VTK's inverse-square attenuation (0, 0, c) is written with
  intensity I / c and takes the node's quadratic output: irradiance pi I cos(theta) / (c d^2);
- VTK directional light of intensity I -> sun of strength pi I (irradiance pi I cos(theta)),
  angle 0, for the same reason;
- a homogeneous volume (VTK's opacity alpha per ScalarOpacityUnitDistance u, colour c) -> a box
  of its bounds with no surface and a volume of extinction density -ln(1 - alpha) / u per
  world unit: Volume Scatter (colour c) plus Volume Absorption (colour c), both of that
  density, so that c of the extinction scatters and 1 - c is absorbed (the transmittance VTK's
  compositing gives a ray, exp(-density x length)). VTK shows an unshaded volume's colour
  unlit, as if lit by radiance 1: c (1 - T) over a ray of transmittance T. That is a Volume
  Emission of colour c and strength equal to the density, seen by camera rays only (it
  lights nothing, as in VTK); the light the volume scatters comes on top, as the pass adds it;
- the renderer's background -> uniform world of that radiance. VTK's ambient term stands for
  that sky: export_scene.py accepts only Ka Ca = background x diffuse colour, which is what the
  unoccluded sky reflects (the world lights the scene in Cycles, occluded and bounced).
"""
import json
import math
import os
import struct
import sys

import bpy
from mathutils import Matrix, Vector

args = sys.argv[sys.argv.index("--") + 1:]
scene_path, prefix, samples, seed = args[:4]
bounces = int(args[4]) if len(args) > 4 else 8
with open(scene_path) as f:
    desc = json.load(f)

bpy.ops.wm.read_factory_settings(use_empty=True)
# no axis conversion: Blender sees VTK's coordinates
bpy.ops.wm.obj_import(filepath=os.path.join(os.path.dirname(scene_path), desc["obj"]),
                      forward_axis='Y', up_axis='Z')
for obj in bpy.context.scene.objects:
    for slot in obj.material_slots:
        material = slot.material
        desc_material = desc["materials"][material.name]
        nodes = material.node_tree.nodes
        links = material.node_tree.links
        nodes.clear()
        output = nodes.new("ShaderNodeOutputMaterial")
        emission = desc_material.get("emission")
        if emission:
            strength = max(emission)
            shader = nodes.new("ShaderNodeEmission")
            shader.inputs["Color"].default_value = (*[c / strength for c in emission], 1.0)
            shader.inputs["Strength"].default_value = strength
        else:
            shader = nodes.new("ShaderNodeBsdfDiffuse")
            shader.inputs["Color"].default_value = (*desc_material["diffuse"], 1.0)
            if desc_material.get("vertex_colors"):
                colors = nodes.new("ShaderNodeAttribute")
                colors.attribute_name = "Color"
                scale = nodes.new("ShaderNodeMixRGB")
                scale.blend_type = 'MULTIPLY'
                scale.inputs["Fac"].default_value = 1.0
                scale.inputs["Color2"].default_value = (*desc_material["diffuse"], 1.0)
                links.new(colors.outputs["Color"], scale.inputs["Color1"])
                links.new(scale.outputs["Color"], shader.inputs["Color"])
            if max(desc_material["specular"]) > 0.0:
                glossy = nodes.new("ShaderNodeBsdfGlossy")
                glossy.distribution = 'BECKMANN'
                share = 8.0 / (desc_material["specular_power"] + 8.0)
                glossy.inputs["Color"].default_value = \
                    (*[share * k for k in desc_material["specular"]], 1.0)
                glossy.inputs["Roughness"].default_value = \
                    (2.0 / (desc_material["specular_power"] + 2.0)) ** 0.25
                both = nodes.new("ShaderNodeAddShader")
                links.new(shader.outputs[0], both.inputs[0])
                links.new(glossy.outputs[0], both.inputs[1])
                shader = both
            if desc_material.get("opacity", 1.0) < 1.0:
                # (1 - opacity) of the light passes, tinted by "transmit" (the surface's colour
                # as much as it is opaque); camera rays see through untinted (VTK blends what
                # lies behind untinted).
                transparent = nodes.new("ShaderNodeBsdfTransparent")
                path = nodes.new("ShaderNodeLightPath")
                tint = nodes.new("ShaderNodeMixRGB")
                tint.inputs["Color1"].default_value = (*desc_material["transmit"], 1.0)
                tint.inputs["Color2"].default_value = (1.0, 1.0, 1.0, 1.0)
                links.new(path.outputs["Is Camera Ray"], tint.inputs["Fac"])
                links.new(tint.outputs["Color"], transparent.inputs["Color"])
                mix = nodes.new("ShaderNodeMixShader")
                mix.inputs["Fac"].default_value = desc_material["opacity"]
                links.new(transparent.outputs[0], mix.inputs[1])
                links.new(shader.outputs[0], mix.inputs[2])
                shader = mix
        links.new(shader.outputs[0], output.inputs["Surface"])

scene = bpy.context.scene
for i, volume in enumerate(desc.get("volumes", [])):
    lo, hi = Vector(volume["bounds"][0::2]), Vector(volume["bounds"][1::2])
    bpy.ops.mesh.primitive_cube_add(size=2.0)
    box = bpy.context.active_object
    box.name = "volume%d" % i
    m = volume["matrix"]
    box.matrix_world = Matrix([m[0:4], m[4:8], m[8:12], m[12:16]]) @ \
        Matrix.Translation((lo + hi) / 2) @ Matrix.Diagonal((*((hi - lo) / 2), 1.0))
    material = bpy.data.materials.new("volume%d" % i)
    material.use_nodes = True
    material.cycles.homogeneous_volume = True
    nodes = material.node_tree.nodes
    links = material.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    scatter = nodes.new("ShaderNodeVolumeScatter")
    absorb = nodes.new("ShaderNodeVolumeAbsorption")
    for node in (scatter, absorb):
        node.inputs["Color"].default_value = (*volume["color"], 1.0)
        node.inputs["Density"].default_value = volume["density"]
    both = nodes.new("ShaderNodeAddShader")
    links.new(scatter.outputs[0], both.inputs[0])
    links.new(absorb.outputs[0], both.inputs[1])
    # VTK's unlit colour, for camera rays only: emission 0 elsewhere.
    emission = nodes.new("ShaderNodeEmission")
    emission.inputs["Color"].default_value = (*volume["color"], 1.0)
    emission.inputs["Strength"].default_value = volume["density"]
    path = nodes.new("ShaderNodeLightPath")
    camera = nodes.new("ShaderNodeMixShader")
    links.new(path.outputs["Is Camera Ray"], camera.inputs["Fac"])
    links.new(emission.outputs[0], camera.inputs[2])
    shown = nodes.new("ShaderNodeAddShader")
    links.new(both.outputs[0], shown.inputs[0])
    links.new(camera.outputs[0], shown.inputs[1])
    links.new(shown.outputs[0], output.inputs["Volume"])
    box.data.materials.append(material)

for i, light in enumerate(desc["lights"]):
    if light["type"] == "directional":
        data = bpy.data.lights.new("light%d" % i, "SUN")
        data.energy = math.pi * light["intensity"]
        data.angle = 0.0
        obj = bpy.data.objects.new("light%d" % i, data)
        # a sun shines along its local -Z
        obj.rotation_euler = Vector((0.0, 0.0, -1.0)).rotation_difference(
            Vector(light["direction"])).to_euler()
    else:
        data = bpy.data.lights.new("light%d" % i, "POINT")
        data.energy = 4.0 * math.pi ** 2 * light["intensity"]
        data.shadow_soft_size = 0.0
        data.use_nodes = True
        falloff = data.node_tree.nodes.new("ShaderNodeLightFalloff")
        falloff.inputs["Strength"].default_value = 1.0  # the light's power scales it
        # VTK's inverse-square attenuation is Cycles' own (quadratic) falloff
        output = "Quadratic" if light.get("falloff") == "inverse_square" else "Constant"
        data.node_tree.links.new(falloff.outputs[output],
                                 data.node_tree.nodes["Emission"].inputs["Strength"])
        obj = bpy.data.objects.new("light%d" % i, data)
        obj.location = light["position"]
    data.color = light["color"]
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

scene.world = bpy.data.worlds.new("sky")
scene.world.use_nodes = True
scene.world.node_tree.nodes["Background"].inputs["Color"].default_value = \
    (*desc["background"], 1.0)
scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0
scene.render.engine = 'CYCLES'
scene.cycles.device = 'CPU'
scene.cycles.samples = int(samples)
scene.cycles.seed = int(seed)
scene.cycles.use_adaptive_sampling = False
scene.cycles.use_denoising = False
scene.cycles.max_bounces = bounces
scene.cycles.diffuse_bounces = bounces
scene.cycles.glossy_bounces = bounces
scene.cycles.volume_bounces = bounces
scene.cycles.transparent_max_bounces = 8
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
