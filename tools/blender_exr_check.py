# Opens frame EXRs with Blender as its compositor does and writes what it read, so that a test can
# compare that with what woven reads (tests/app/exr_readers_test.cpp):
#   blender -b --factory-startup --python tools/blender_exr_check.py -- IN.exr WIDTH HEIGHT OUT.exr [...]
# For each IN (WIDTH x HEIGHT as woven reads it) it prints "IN: passes NAME,NAME,..." (the
# Image node's outputs: the passes Blender found in the file's first layer) and renders the
# compositor, the Image node's beauty into the Composite node, at WIDTH x HEIGHT to OUT (RGB, 32-bit
# float). bpy.data.images.load alone reports every multi-layer EXR, Blender's own renders
# included, as 0 x 0: only an image user (a node, an editor) picks a layer, so a node is how
# Blender opens one. An image read at another size lands shifted (centred) or edge-extended, so
# OUT equals IN's beauty pixel for pixel only when Blender read it at its size.
import sys

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
if not args or len(args) % 4:
    sys.exit("usage: blender -b --python blender_exr_check.py -- IN.exr WIDTH HEIGHT OUT.exr [...]")
scene = bpy.context.scene
scene.use_nodes = True
tree = scene.node_tree
scene.render.resolution_percentage = 100
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_mode = "RGB"
scene.render.image_settings.color_depth = "32"
for i in range(0, len(args), 4):
    path, width, height, out = args[i], int(args[i + 1]), int(args[i + 2]), args[i + 3]
    for node in list(tree.nodes):
        tree.nodes.remove(node)
    image = bpy.data.images.load(path, check_existing=False)
    node = tree.nodes.new("CompositorNodeImage")
    node.image = image
    print(path + ": passes " + ",".join(o.name for o in node.outputs if o.enabled), flush=True)
    composite = tree.nodes.new("CompositorNodeComposite")
    tree.links.new(node.outputs[0], composite.inputs["Image"])  # the beauty, "Combined"
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.filepath = out
    bpy.ops.render.render(write_still=True)
