# Times Blender's Fog Glow (compositor Glare node) on one EXR frame, for the
# comparison in docs/performance.md with eyestream's glare engines. Not part of the build
# or the tests: it needs Blender (Debian package `blender`).
#
#   blender -b --factory-startup --python bench/fog_glow.py -- IN.exr OUT.exr [THRESHOLD] [RUNS]
#
# Prints the time of each compositing run (the first includes loading) and
# the frame's total light before and after, per channel.
import sys
import time

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
source, target = args[0], args[1]
threshold = float(args[2]) if len(args) > 2 else 100.0
runs = int(args[3]) if len(args) > 3 else 3

image = bpy.data.images.load(source)
width, height = image.size
scene = bpy.context.scene
scene.render.resolution_x, scene.render.resolution_y = width, height
scene.render.resolution_percentage = 100
scene.render.use_compositing = True
scene.render.use_sequencer = False
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.filepath = target
scene.view_settings.view_transform = "Standard"
scene.use_nodes = True
tree = scene.node_tree
for node in list(tree.nodes):
    tree.nodes.remove(node)
picture = tree.nodes.new("CompositorNodeImage")
picture.image = image
glare = tree.nodes.new("CompositorNodeGlare")
glare.glare_type = "FOG_GLOW"
glare.quality = "HIGH"
glare.size = 9  # the largest kernel Blender offers
glare.mix = 0.0
glare.threshold = threshold
out = tree.nodes.new("CompositorNodeComposite")
tree.links.new(picture.outputs["Image"], glare.inputs["Image"])
tree.links.new(glare.outputs["Image"], out.inputs["Image"])

for run in range(runs):
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    print("fog glow run %d: %.1f ms (%dx%d)" % (run, 1000 * (time.perf_counter() - start), width, height))


def totals(img):
    pixels = list(img.pixels)
    return [sum(pixels[c::4]) for c in range(3)]


result = bpy.data.images.load(target)
print("total light in:  %.6g %.6g %.6g" % tuple(totals(image)))
print("total light out: %.6g %.6g %.6g" % tuple(totals(result)))
