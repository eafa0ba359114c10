"""Render a glTF file with Blender Cycles as a reference for woven.

Run inside Blender (3.4 or later), never with a plain Python:

    blender -b --factory-startup --python-exit-code 1 --python cycles_render.py -- \
        --gltf MODEL.glb --bounds-only
    blender -b --factory-startup --python-exit-code 1 --python cycles_render.py -- \
        --gltf MODEL.glb --out ref.exr --camera '{"position": [...], "target": [...],
        "up": [...], "yfov_degrees": 39.6}' --width 320 --height 240 --samples 64 \
        --max-depth 8 --world-color 1 1 1

Everything here is in Blender's coordinates (+Z up). Blender's glTF importer turns glTF's +Y up
into +Z up, blender (x, y, z) = gltf (x, -z, y); compare.py converts cameras and bounds.

Output: a linear float RGBA OpenEXR. The film is transparent, so alpha is the fraction of the
pixel that the object covers (glass counts as covering). One line on stdout starts with
"CYCLES_BOUNDS " and holds the world-space bounding box of the evaluated meshes as JSON.
"""

import argparse
import json
import math
import os
import sys
import time

import bpy
import mathutils

BOUNDS_TAG = "CYCLES_BOUNDS "


class RenderError(Exception):
    """A failure with a message meant for the person running the harness."""


def parse_args(argv):
    # Blender keeps its own arguments; ours come after "--".
    argv = argv[argv.index("--") + 1:] if "--" in argv else []
    p = argparse.ArgumentParser(prog="cycles_render.py", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--gltf", required=True, help="glTF 2.0 file (.gltf or .glb)")
    p.add_argument("--bounds-only", action="store_true",
                   help="import, print the bounds and stop (no render)")
    p.add_argument("--out", help="output .exr (required unless --bounds-only)")
    p.add_argument("--camera", help="JSON: position, target, up (Blender coordinates), yfov_degrees")
    p.add_argument("--width", type=int, default=320)
    p.add_argument("--height", type=int, default=240)
    p.add_argument("--samples", type=int, default=64)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--max-depth", type=int, default=8,
                   help="woven's --max-depth: scattering vertices, 1 = direct light only")
    p.add_argument("--transparent-bounces", type=int, default=16,
                   help="alpha pass-throughs allowed (they do not count as bounces)")
    p.add_argument("--world-color", type=float, nargs=3, default=[1.0, 1.0, 1.0],
                   help="uniform world radiance, linear RGB (multiplies --world-image)")
    p.add_argument("--world-image", help="equirectangular .hdr/.exr, laid out as woven does")
    p.add_argument("--world-rotation", type=float, default=0.0,
                   help="degrees about the up axis, as woven's environment.rotation")
    p.add_argument("--threads", type=int, default=0, help="render threads (0: all cores)")
    p.add_argument("--keep-light-size", action="store_true",
                   help="keep the importer's light sizes (0.25 m radius, 0.53 deg sun) instead of points")
    p.add_argument("--lambert", action="store_true",
                   help="every material becomes a Lambertian Diffuse BSDF of its base colour, its emission kept")
    p.add_argument("--diffuse-transmission", action="store_true",
                   help="each material with KHR_materials_diffuse_transmission in the file becomes "
                        "Mix(Diffuse, Translucent) by its factor (Blender 3.4's importer ignores the extension)")
    p.add_argument("--keep-animation", action="store_true",
                   help="keep the first glTF animation active (default: static node transforms)")
    args = p.parse_args(argv)
    if not args.bounds_only and (not args.out or not args.camera):
        p.error("--out and --camera are required unless --bounds-only")
    if args.max_depth < 1:
        p.error("--max-depth must be at least 1")
    return args


def clear_scene():
    # --factory-startup still brings the default cube, camera and light.
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    for collection in (bpy.data.meshes, bpy.data.lights, bpy.data.cameras, bpy.data.materials,
                       bpy.data.images, bpy.data.worlds):
        for block in list(collection):
            collection.remove(block)


def skip_gltf_animations():
    """Stop the importer from making the first animation active.

    woven renders the static scene that the glTF node transforms describe; Blender's importer
    would otherwise pose skins and nodes at the first animation's first key. Skipping
    create_animations leaves every node (and joint) at its static TRS.
    """
    from io_scene_gltf2.blender.imp import gltf2_blender_scene
    gltf2_blender_scene.BlenderScene.create_animations = staticmethod(lambda gltf: None)


def patch_numpy_bool():
    """Debian 12's Blender 3.4.1 importer uses np.bool, which numpy 1.24 removed.

    Without this, importing any mesh fails in set_poly_smoothing with
    "module 'numpy' has no attribute 'bool'". np.bool was an alias of bool.
    """
    import numpy
    if "bool" not in numpy.__dict__:
        numpy.bool = bool


def import_gltf(path, keep_animation):
    if not os.path.isfile(path):
        raise RenderError(f"{path}: no such file")
    patch_numpy_bool()
    if not keep_animation:
        skip_gltf_animations()
    try:
        result = bpy.ops.import_scene.gltf(filepath=path)
    except RuntimeError as e:  # the importer reports its errors as RuntimeError
        raise RenderError(f"{path}: Blender's glTF importer failed: {e}") from None
    if "FINISHED" not in result:
        raise RenderError(f"{path}: Blender's glTF importer returned {result}")
    check_images(path)
    if not any(o.type == "MESH" for o in bpy.data.objects):
        raise RenderError(f"{path}: no meshes were imported")


def check_images(path):
    # A missing texture only logs an error in the importer and leaves a placeholder image;
    # a reference rendered without its textures is worse than none.
    for image in bpy.data.images:
        if image.source != "FILE" or image.packed_file is not None:
            continue
        file = bpy.path.abspath(image.filepath)
        if not os.path.isfile(file):
            raise RenderError(f"{path}: texture '{image.name}' is missing ({file})")


def make_lights_punctual():
    """Shrink imported lights to points, as KHR_lights_punctual (and woven) define them.

    The importer sets only type, colour, energy and spot angles, so every light keeps
    bpy.data.lights.new's defaults: a 0.25 m radius for point and spot lights (soft shadows,
    and a visible sphere) and a 0.53 degree disc for sun lights.
    """
    for light in bpy.data.lights:
        if light.type in ("POINT", "SPOT"):
            light.shadow_soft_size = 0.0
        elif light.type == "SUN":
            light.angle = 0.0


def make_materials_lambertian():
    """Each material's Principled BSDF replaced by a Diffuse BSDF (Lambert) of its base colour.

    For scenes meant to be Lambertian, as the Lambert box of tools/cycles_compare/efficiency.py:
    Blender 3.4's importer drops KHR_materials_specular's specularFactor (its Principled keeps
    specular 0.5, F0 = 0.04) and the Principled diffuse is Burley's, brighter than Lambert's at
    grazing angles and rough, where woven reads a glTF base colour as Lambert's. Emission stays.
    """
    for material in bpy.data.materials:
        if not material.use_nodes:
            continue
        nodes, links = material.node_tree.nodes, material.node_tree.links
        principled = next((n for n in nodes if n.type == "BSDF_PRINCIPLED"), None)
        output = next((n for n in nodes if n.type == "OUTPUT_MATERIAL"), None)
        if principled is None or output is None:
            raise RenderError(f"--lambert: material '{material.name}' has no Principled BSDF and output")
        if principled.inputs["Base Color"].is_linked:
            raise RenderError(f"--lambert: material '{material.name}' has a base colour texture")
        diffuse = nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Color"].default_value = principled.inputs["Base Color"].default_value
        diffuse.inputs["Roughness"].default_value = 0.0  # Oren-Nayar at 0 is Lambert
        emission = nodes.new("ShaderNodeEmission")
        emission.inputs["Color"].default_value = principled.inputs["Emission"].default_value
        emission.inputs["Strength"].default_value = principled.inputs["Emission Strength"].default_value
        add = nodes.new("ShaderNodeAddShader")
        links.new(add.inputs[0], diffuse.outputs["BSDF"])
        links.new(add.inputs[1], emission.outputs["Emission"])
        links.new(output.inputs["Surface"], add.outputs["Shader"])


def make_materials_diffuse_transmission(gltf_path):
    """KHR_materials_diffuse_transmission's definition in Cycles' nodes, from the file's values.

    The extension makes the diffuse base mix(diffuse_brdf(baseColor), diffuse_btdf(colour),
    factor), under the specular layer. For files whose KHR_materials_specular sets
    specularFactor 0 (no specular layer) that is exactly Mix(Diffuse BSDF (Lambert: roughness
    0), Translucent BSDF) with the factor as Fac; the specular layer is not rebuilt here, so a
    material with one is refused. Textures are refused too (the factors only).
    """
    with open(gltf_path, "rb") as f:
        data = f.read()
    if data[:4] == b"glTF":
        length = int.from_bytes(data[12:16], "little")
        document = json.loads(data[20:20 + length])
    else:
        document = json.loads(data)
    for source in document.get("materials", []):
        extensions = source.get("extensions", {})
        transmission = extensions.get("KHR_materials_diffuse_transmission")
        if transmission is None:
            continue
        name = source.get("name", "")
        if extensions.get("KHR_materials_specular", {}).get("specularFactor", 1.0) != 0.0:
            raise RenderError(f"--diffuse-transmission: material '{name}' has a specular layer (specularFactor is not 0)")
        if "diffuseTransmissionTexture" in transmission or "diffuseTransmissionColorTexture" in transmission:
            raise RenderError(f"--diffuse-transmission: material '{name}' has textures")
        pbr = source.get("pbrMetallicRoughness", {})
        if pbr.get("metallicFactor", 1.0) != 0.0 or "baseColorTexture" in pbr:
            raise RenderError(f"--diffuse-transmission: material '{name}' must be a dielectric without textures")
        material = bpy.data.materials.get(name)
        if material is None or not material.use_nodes:
            raise RenderError(f"--diffuse-transmission: Blender imported no material '{name}'")
        nodes, links = material.node_tree.nodes, material.node_tree.links
        output = next((n for n in nodes if n.type == "OUTPUT_MATERIAL"), None)
        diffuse = nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Color"].default_value = pbr.get("baseColorFactor", [1.0, 1.0, 1.0, 1.0])
        diffuse.inputs["Roughness"].default_value = 0.0  # Oren-Nayar at 0 is Lambert
        translucent = nodes.new("ShaderNodeBsdfTranslucent")
        translucent.inputs["Color"].default_value = list(transmission.get("diffuseTransmissionColorFactor", [1.0, 1.0, 1.0])) + [1.0]
        mix = nodes.new("ShaderNodeMixShader")
        mix.inputs["Fac"].default_value = transmission.get("diffuseTransmissionFactor", 0.0)
        links.new(mix.inputs[1], diffuse.outputs["BSDF"])
        links.new(mix.inputs[2], translucent.outputs["BSDF"])
        links.new(output.inputs["Surface"], mix.outputs["Shader"])
        print(f"cycles_render: material '{name}' = Mix(Diffuse, Translucent) by {mix.inputs['Fac'].default_value}", flush=True)


def world_bounds():
    """Bounding box of every evaluated mesh (skins and modifiers applied), world space."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    lo = [math.inf] * 3
    hi = [-math.inf] * 3
    for obj in bpy.data.objects:
        if obj.type != "MESH" or obj.hide_render:
            continue
        evaluated = obj.evaluated_get(depsgraph)
        mesh = evaluated.to_mesh()
        matrix = evaluated.matrix_world
        for v in mesh.vertices:
            p = matrix @ v.co
            for i in range(3):
                lo[i] = min(lo[i], p[i])
                hi[i] = max(hi[i], p[i])
        evaluated.to_mesh_clear()
    if lo[0] > hi[0]:
        raise RenderError("the imported meshes have no vertices")
    return {"min": lo, "max": hi}


def look_at_matrix(position, target, up):
    """Camera-to-world with the camera looking down -Z, +Y up (Blender's and glTF's camera)."""
    eye = mathutils.Vector(position)
    z = (eye - mathutils.Vector(target)).normalized()
    x = mathutils.Vector(up).cross(z)
    if x.length < 1e-8:
        raise RenderError("camera up is parallel to the view direction")
    x.normalize()
    y = z.cross(x)
    m = mathutils.Matrix.Identity(4)
    for row in range(3):
        m[row][0], m[row][1], m[row][2], m[row][3] = x[row], y[row], z[row], eye[row]
    return m


def setup_camera(scene, camera_json, width, height):
    try:
        cam = json.loads(camera_json)
        position, target = cam["position"], cam["target"]
        up = cam.get("up", [0.0, 0.0, 1.0])
        yfov = math.radians(float(cam.get("yfov_degrees", 39.6)))
    except (ValueError, KeyError, TypeError) as e:
        raise RenderError(f"--camera: {e}") from None
    data = bpy.data.cameras.new("ReferenceCamera")
    data.type = "PERSP"
    # The vertical field of view fixes the image; the width follows from the aspect ratio,
    # as in woven (and glTF's yfov).
    data.sensor_fit = "VERTICAL"
    data.angle_y = yfov
    data.clip_start = 1e-4
    data.clip_end = 1e6
    obj = bpy.data.objects.new("ReferenceCamera", data)
    scene.collection.objects.link(obj)
    obj.matrix_world = look_at_matrix(position, target, up)
    scene.camera = obj
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.render.resolution_percentage = 100
    scene.render.pixel_aspect_x = 1.0
    scene.render.pixel_aspect_y = 1.0


def setup_world(scene, color, image_path, rotation_degrees):
    world = bpy.data.worlds.new("ReferenceWorld")
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    nodes.clear()
    background = nodes.new("ShaderNodeBackground")
    background.inputs["Color"].default_value = (*color, 1.0)
    background.inputs["Strength"].default_value = 1.0
    output = nodes.new("ShaderNodeOutputWorld")
    links.new(output.inputs["Surface"], background.outputs["Background"])
    if image_path:
        add_world_image(world, background, image_path, color, rotation_degrees)
    scene.world = world


def add_world_image(world, background, image_path, color, rotation_degrees):
    """Equirect image times color, oriented as woven's environment.image.

    woven (glTF, +Y up) reads u = atan2(d.x, -d.z) / 2pi after rotating d by -rotation about +Y.
    Blender's Environment Texture reads u = 0.5 - atan2(d.y, d.x) / 2pi. With
    blender = (x, -z, y) the two differ by a quarter turn about +Z, so the lookup vector is
    rotated by (90 deg - rotation) about Blender's +Z (= glTF +Y) before the texture.
    """
    if not os.path.isfile(image_path):
        raise RenderError(f"{image_path}: no such file")
    nodes, links = world.node_tree.nodes, world.node_tree.links
    coords = nodes.new("ShaderNodeTexCoord")
    mapping = nodes.new("ShaderNodeMapping")
    mapping.vector_type = "VECTOR"
    mapping.inputs["Rotation"].default_value = (0.0, 0.0, math.radians(90.0 - rotation_degrees))
    texture = nodes.new("ShaderNodeTexEnvironment")
    texture.image = bpy.data.images.load(os.path.abspath(image_path))
    texture.projection = "EQUIRECTANGULAR"
    texture.interpolation = "Linear"
    multiply = nodes.new("ShaderNodeMix")
    multiply.data_type = "RGBA"
    multiply.blend_type = "MULTIPLY"
    multiply.inputs["Factor"].default_value = 1.0
    multiply.inputs[7].default_value = (*color, 1.0)  # B (colour) of the RGBA mix
    links.new(mapping.inputs["Vector"], coords.outputs["Generated"])
    links.new(texture.inputs["Vector"], mapping.outputs["Vector"])
    links.new(multiply.inputs[6], texture.outputs["Color"])  # A (colour) of the RGBA mix
    links.new(background.inputs["Color"], multiply.outputs[2])  # Result (colour)


def setup_cycles(scene, args):
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.samples = args.samples
    c.seed = args.seed
    c.use_animated_seed = False
    c.use_adaptive_sampling = False  # a fixed sample count, as woven
    c.use_denoising = False
    c.use_preview_denoising = False
    # woven's --max-depth counts scattering vertices (1 = direct light only); Cycles counts
    # bounces after the first hit (0 = direct light only).
    bounces = args.max_depth - 1
    c.max_bounces = bounces
    c.diffuse_bounces = bounces
    c.glossy_bounces = bounces
    c.transmission_bounces = bounces
    c.volume_bounces = bounces
    c.transparent_max_bounces = args.transparent_bounces
    # Unbiased settings: no clamping, no glossy blur, every light sampled.
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0
    c.caustics_reflective = True
    c.caustics_refractive = True
    c.light_sampling_threshold = 0.0
    # A box filter one pixel wide = uniform samples over the pixel, as woven.
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    scene.render.film_transparent = True  # alpha = coverage
    c.film_transparent_glass = False      # glass covers its pixels
    if args.threads > 0:
        scene.render.threads_mode = "FIXED"
        scene.render.threads = args.threads
    # Colour management only touches displayed images; the EXR stays scene-linear.
    scene.display_settings.display_device = "sRGB"
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.render.use_compositing = False
    scene.render.use_sequencer = False


def render_exr(scene, out):
    out = os.path.abspath(out)
    os.makedirs(os.path.dirname(out), exist_ok=True)
    settings = scene.render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_mode = "RGBA"
    settings.color_depth = "32"
    settings.exr_codec = "ZIP"
    scene.render.filepath = out
    scene.render.use_file_extension = False
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    # Scene sync, BVH, rendering and the EXR write: what efficiency.py counts as render time.
    print(f"CYCLES_RENDER_SECONDS {time.perf_counter() - start:.4f}", flush=True)
    if not os.path.isfile(out):
        raise RenderError(f"Cycles wrote no image to {out}")


def main():
    args = parse_args(sys.argv)
    clear_scene()
    import_gltf(os.path.abspath(args.gltf), args.keep_animation)
    print(BOUNDS_TAG + json.dumps(world_bounds()), flush=True)
    if args.bounds_only:
        return
    scene = bpy.context.scene
    scene.frame_set(scene.frame_start)
    setup_camera(scene, args.camera, args.width, args.height)
    setup_world(scene, args.world_color, args.world_image, args.world_rotation)
    setup_cycles(scene, args)
    if not args.keep_light_size:
        make_lights_punctual()
    if args.lambert:
        make_materials_lambertian()
    if args.diffuse_transmission:
        make_materials_diffuse_transmission(os.path.abspath(args.gltf))
    render_exr(scene, args.out)
    print(f"cycles_render: wrote {os.path.abspath(args.out)}", flush=True)


if __name__ == "__main__":
    try:
        main()
    except RenderError as e:
        print(f"cycles_render: error: {e}", file=sys.stderr, flush=True)
        sys.exit(2)
