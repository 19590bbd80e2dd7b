"""The Blender add-on (blender/vernacular_blender), headless: installed from
its zip as a user installs it, it infers a style from a collection of
three houses (windows set into walls; one house's windows made by an Array
modifier), generates variants into a collection beside them, derives again
when the seed or the grammar's text changes, and says where a broken
grammar fails without losing the variants.
   blender -b --factory-startup --python-exit-code 1 --python addon_test.py -- ZIP MODULE_DIR
"""

import os
import sys
import tempfile

import bpy


def fail(message):
    print("blender addon: FAIL: " + message)
    sys.exit(1)


args = sys.argv[sys.argv.index("--") + 1:]
zip_path, module_dir = args[0], args[1]
sys.path.insert(0, module_dir)  # the build's module, before any installed one
import vernacular  # noqa: E402

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
bpy.ops.preferences.addon_enable(module="vernacular_blender")
import vernacular_blender  # noqa: E402


def add_box(name, lo, hi, collection):
    mesh = bpy.data.meshes.new(name)
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    verts = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0), (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    faces = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    mesh.from_pydata(verts, [], faces)
    ob = bpy.data.objects.new(name, mesh)
    collection.objects.link(ob)
    return ob


scene = bpy.context.scene
houses = bpy.data.collections.new("Houses")
scene.collection.children.link(houses)
x = 0.0
for bays in (2, 3, 4):
    width = 2.4 * bays
    add_box("wall", (x, 0, 0), (x + width, 5, 3), houses)
    add_box("roof", (x, 0, 3), (x + width, 5, 4.5), houses)
    if bays == 4:
        # One window and an Array modifier: four windows, 2.4 m apart.
        window = add_box("window", (x + 0.7, 0, 1), (x + 1.7, 0.2, 2.2), houses)
        array = window.modifiers.new("bays", "ARRAY")
        array.count = 4
        array.use_relative_offset = False
        array.use_constant_offset = True
        array.constant_offset_displace = (2.4, 0, 0)
    else:
        for i in range(bays):
            left = x + 2.4 * i + 0.7
            add_box("window", (left, 0, 1), (left + 1, 0.2, 2.2), houses)
    x += width + 4

settings = scene.vernacular
settings.folder = tempfile.mkdtemp(prefix="vernacular_addon_test_")
settings.source = houses
settings.count = 4
if bpy.ops.vernacular.infer() != {"FINISHED"}:
    fail("infer: " + settings.status)
text = settings.grammar
if text is None or "split" not in text.as_string():
    fail("no grammar text after infer")
print("blender addon: inferred\n" + text.as_string())

# The examples as the add-on wrote them: three houses, the Array's windows
# four parts, and the grammar derives each.
examples = vernacular.read_examples([os.path.join(settings.folder, "examples.obj")])
if len(examples) != 3:
    fail("%d examples, expected 3 houses" % len(examples))
windows = sorted(e.labels.count("window") for e in examples)
if windows != [2, 3, 4]:
    fail("windows per house %s, expected [2, 3, 4] (the Array modifier applied)" % windows)
grammar = vernacular.Grammar.parse(text.as_string(), folder=settings.folder)
for e in examples:
    if not vernacular.check(grammar, e):
        fail(e.source + " is not derivable from the inferred grammar")

variants = settings.variants
if variants is None or variants.name != "Houses variants":
    fail("no variants collection")
if variants.name not in scene.collection.children:
    fail("the variants are not beside the examples")
labels = {ob.name.split(".")[0] for ob in variants.objects}
if not labels or not labels <= {"wall", "roof", "window"}:
    fail("variants' objects named %s" % sorted(labels))
_, houses_hi = vernacular_blender._bounds(houses.all_objects)
variants_lo, _ = vernacular_blender._bounds(variants.objects)
if variants_lo[0] < houses_hi[0]:
    fail("the variants overlap the examples along x (%g < %g)" % (variants_lo[0], houses_hi[0]))


def fingerprint():
    return sorted((ob.name.split(".")[0], round(ob.dimensions.x, 4), round(ob.dimensions.z, 4),
                   round(ob.location.x, 4)) for ob in variants.objects)


first = fingerprint()
settings.seed = 7  # re-derives (the property's update)
after_seed = fingerprint()
if after_seed == first:
    fail("changing the seed left the variants as they were")
print("blender addon: %d objects, another seed: %d objects" % (len(first), len(after_seed)))

text.from_string(text.as_string().replace("I(window)", "I(door)"))
vernacular_blender.watch_grammars()  # the timer's work, run now
doors = [ob for ob in variants.objects if ob.name.startswith("door")]
if not doors:
    fail("editing the grammar's text did not derive again: " + settings.status)

before_broken = fingerprint()
text.from_string(text.as_string() + "\nbroken --> split(x){ 1 : \n")
vernacular_blender.watch_grammars()
if fingerprint() != before_broken:
    fail("a broken grammar changed the variants")
if ".grm:" not in settings.status or "error" not in settings.status:
    fail("a broken grammar's error does not say where: " + settings.status)
print("blender addon: broken grammar said: " + settings.status)
print("blender addon: passed")
