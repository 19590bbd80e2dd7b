"""Vernacular for Blender: infer a style from a collection of example
buildings, and generate new buildings in it beside them.

The panel (3D view > sidebar > Vernacular) takes a collection of buildings
modelled in Blender, each part an object named by its label (wall,
window.001, roof, ...), windows set into walls or not, modifiers and all:
Infer writes the style as a grammar into a text block, which you can edit;
Generate derives buildings from it into a collection beside the examples,
again whenever the seed, the count or the grammar's text changes.

The work is done by the Python module vernacular (python/ in the project;
its set-up installs it where Blender's Python finds it).
"""

bl_info = {
    "name": "Vernacular",
    "author": "Vernacular",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > Vernacular",
    "description": "Infer a grammar of a style from example buildings, generate new buildings in it",
    "category": "Object",
}

import hashlib
import os
import sys
import tempfile

import bpy
import mathutils

ADDON = __name__


def _module():
    """The vernacular module, or an ImportError that says what to do."""
    prefs = bpy.context.preferences.addons[ADDON].preferences if ADDON in bpy.context.preferences.addons else None
    extra = getattr(prefs, "module_path", "") if prefs else ""
    if extra and extra not in sys.path:
        sys.path.insert(0, extra)
    try:
        import vernacular
    except ImportError as e:
        raise ImportError("Blender's Python cannot import the module vernacular (%s): run the project's "
                          "scripts/setup, which installs it, or give its folder in the add-on's preferences" % e)
    return vernacular


def _folder(settings):
    """Where the examples, the grammar's meshes and the variants are written."""
    if not settings.folder:
        settings.folder = tempfile.mkdtemp(prefix="vernacular_")
    os.makedirs(bpy.path.abspath(settings.folder), exist_ok=True)
    return bpy.path.abspath(settings.folder)


def write_examples(collection, path):
    """The collection's mesh objects as one OBJ, z up, in world space, each
    object's mesh as evaluated (modifiers applied: an Array modifier's
    windows are windows)."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    lines = ["# Vernacular examples from Blender's collection '%s'" % collection.name, "# up z"]
    first = 1
    parts = 0
    for ob in sorted(collection.all_objects, key=lambda o: o.name):
        if ob.type != "MESH":
            continue
        evaluated = ob.evaluated_get(depsgraph)
        mesh = evaluated.to_mesh()
        try:
            if not mesh.polygons:
                continue
            lines.append("o " + ob.name)
            world = evaluated.matrix_world
            for v in mesh.vertices:
                w = world @ v.co
                lines.append("v %.6f %.6f %.6f" % (w.x, w.y, w.z))
            for p in mesh.polygons:
                lines.append("f " + " ".join(str(first + i) for i in p.vertices))
            first += len(mesh.vertices)
            parts += 1
        finally:
            evaluated.to_mesh_clear()
    if parts == 0:
        raise ValueError("the collection '%s' holds no mesh objects: put the example buildings' parts in it"
                         % collection.name)
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return parts


def _grammar(settings):
    vernacular = _module()
    text = settings.grammar
    if text is None:
        raise ValueError("no grammar: infer one from a collection first, or choose a text block")
    return vernacular.Grammar.parse(text.as_string(), name=text.name, folder=_folder(settings))


def _clear(collection):
    for ob in list(collection.objects):
        data = ob.data
        bpy.data.objects.remove(ob, do_unlink=True)
        if data is not None and data.users == 0 and isinstance(data, bpy.types.Mesh):
            bpy.data.meshes.remove(data)


def _parent_of(collection, scene):
    """The collection that holds `collection` (the scene's own if none)."""
    for c in [scene.collection] + list(bpy.data.collections):
        if collection.name in c.children:
            return c
    return scene.collection


def _bounds(objects):
    lo = [float("inf")] * 3
    hi = [float("-inf")] * 3
    for ob in objects:
        if ob.type != "MESH":
            continue
        for corner in ob.bound_box:
            w = ob.matrix_world @ mathutils.Vector(corner)
            for i in range(3):
                lo[i] = min(lo[i], w[i])
                hi[i] = max(hi[i], w[i])
    return lo, hi


def generate(scene):
    """Derives the settings' buildings into the variants collection (made
    beside the examples' collection), replacing what it held. Raises
    vernacular.Error and ValueError with what to do."""
    settings = scene.vernacular
    vernacular = _module()
    grammar = _grammar(settings)
    buildings = vernacular.derive_many(grammar, settings.count, seed=settings.seed)
    path = os.path.join(_folder(settings), "variants.obj")
    vernacular.write_buildings(buildings, grammar, path, spacing=settings.spacing)
    source = settings.source
    name = (source.name if source else settings.grammar.name) + " variants"
    variants = settings.variants
    if variants is None:
        variants = bpy.data.collections.new(name)
        (_parent_of(source, scene) if source else scene.collection).children.link(variants)
        settings.variants = variants
    _clear(variants)
    # Imported into the variants collection: made active for the import.
    layer = _layer_collection(bpy.context.view_layer.layer_collection, variants)
    previous = bpy.context.view_layer.active_layer_collection
    if layer is not None:
        bpy.context.view_layer.active_layer_collection = layer
    try:
        bpy.ops.wm.obj_import(filepath=path)
    finally:
        bpy.context.view_layer.active_layer_collection = previous
    # Beside the examples: past their largest x, a spacing apart.
    if source is not None and source.all_objects:
        _, hi = _bounds(source.all_objects)
        lo, _ = _bounds(variants.objects)
        shift = hi[0] + settings.spacing - lo[0]
        for ob in variants.objects:
            ob.location.x += shift
    settings.status = "%d buildings, %d parts (seed %d)" % (len(buildings), sum(len(b) for b in buildings), settings.seed)
    settings.grammar_hash = _hash(settings.grammar)
    return len(buildings)


def _layer_collection(layer, collection):
    if layer.collection == collection:
        return layer
    for child in layer.children:
        found = _layer_collection(child, collection)
        if found is not None:
            return found
    return None


def _hash(text):
    return hashlib.sha1(text.as_string().encode()).hexdigest() if text is not None else ""


def _say(settings, error):
    settings.status = str(error).splitlines()[0]
    print("vernacular: " + str(error))


def _rederive(self, context):
    """On a change of seed, count or spacing: the variants again."""
    scene = context.scene if context and context.scene else None
    if scene is None or scene.vernacular.grammar is None or scene.vernacular.variants is None:
        return
    try:
        generate(scene)
    except Exception as e:  # shown in the panel; the variants stay as they were
        _say(scene.vernacular, e)


def watch_grammars():
    """Re-derives every scene whose grammar text changed since its variants
    were made (a timer, twice a second). A grammar that does not read
    leaves the variants as they are and says where it fails."""
    for scene in bpy.data.scenes:
        settings = scene.vernacular
        if not settings.live or settings.grammar is None or settings.variants is None:
            continue
        current = _hash(settings.grammar)
        if current == settings.grammar_hash:
            continue
        try:
            generate(scene)
        except Exception as e:
            settings.grammar_hash = current  # said once, not twice a second
            _say(settings, e)
    return 0.5


class VernacularPreferences(bpy.types.AddonPreferences):
    bl_idname = ADDON
    module_path: bpy.props.StringProperty(
        name="Module folder", subtype="DIR_PATH",
        description="A folder holding the vernacular Python module, where Blender's Python does not find it")

    def draw(self, context):
        self.layout.prop(self, "module_path")


class VernacularSettings(bpy.types.PropertyGroup):
    source: bpy.props.PointerProperty(type=bpy.types.Collection, name="Examples",
                                      description="The collection of example buildings to infer a style from")
    grammar: bpy.props.PointerProperty(type=bpy.types.Text, name="Grammar",
                                       description="The style's grammar (a text block you may edit)")
    variants: bpy.props.PointerProperty(type=bpy.types.Collection, name="Variants")
    count: bpy.props.IntProperty(name="Count", default=6, min=1, max=10000, update=_rederive)
    seed: bpy.props.IntProperty(name="Seed", default=1, min=0, update=_rederive)
    spacing: bpy.props.FloatProperty(name="Spacing", default=5.0, min=0.0, unit="LENGTH", update=_rederive)
    tolerance: bpy.props.FloatProperty(name="Noise level", default=0.0, min=0.0, unit="LENGTH",
                                       description="Coordinates closer than this are one (0: the file's precision)")
    live: bpy.props.BoolProperty(name="Live", default=True,
                                 description="Derive again whenever the grammar's text changes")
    folder: bpy.props.StringProperty(name="Folder", subtype="DIR_PATH",
                                     description="Where the examples, meshes and variants are written "
                                                 "(default: a temporary folder)")
    status: bpy.props.StringProperty(name="Status")
    grammar_hash: bpy.props.StringProperty()


class VERNACULAR_OT_infer(bpy.types.Operator):
    """Infer a grammar of the examples' style, then generate buildings in it"""
    bl_idname = "vernacular.infer"
    bl_label = "Infer style"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        settings = context.scene.vernacular
        source = settings.source or context.collection
        try:
            vernacular = _module()
            folder = _folder(settings)
            examples_path = os.path.join(folder, "examples.obj")
            write_examples(source, examples_path)
            examples = vernacular.read_examples([examples_path], tolerance=settings.tolerance)
            result = vernacular.infer(examples, tolerance=settings.tolerance)
            style_path = os.path.join(folder, "style.grm")
            result.save(style_path)
            text = settings.grammar or bpy.data.texts.new(source.name + ".grm")
            with open(style_path) as f:
                text.from_string(f.read())
            settings.source = source
            settings.grammar = text
            for w in result.warnings:
                self.report({"WARNING"}, w)
            self.report({"INFO"}, "%d examples -> %d rules" % (len(examples), result.grammar.rule_count))
            generate(context.scene)
        except Exception as e:
            _say(settings, e)
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        return {"FINISHED"}


class VERNACULAR_OT_generate(bpy.types.Operator):
    """Derive buildings from the grammar into the variants collection"""
    bl_idname = "vernacular.generate"
    bl_label = "Generate"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        try:
            generate(context.scene)
        except Exception as e:
            _say(context.scene.vernacular, e)
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        return {"FINISHED"}


class VIEW3D_PT_vernacular(bpy.types.Panel):
    bl_label = "Vernacular"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Vernacular"

    def draw(self, context):
        settings = context.scene.vernacular
        layout = self.layout
        layout.prop(settings, "source")
        layout.prop(settings, "tolerance")
        layout.operator(VERNACULAR_OT_infer.bl_idname)
        layout.separator()
        layout.prop(settings, "grammar")
        row = layout.row()
        row.prop(settings, "count")
        row.prop(settings, "seed")
        layout.prop(settings, "spacing")
        layout.prop(settings, "live")
        layout.operator(VERNACULAR_OT_generate.bl_idname)
        layout.prop(settings, "folder")
        if settings.status:
            layout.label(text=settings.status)


_classes = (VernacularPreferences, VernacularSettings, VERNACULAR_OT_infer, VERNACULAR_OT_generate,
            VIEW3D_PT_vernacular)


def register():
    for c in _classes:
        bpy.utils.register_class(c)
    bpy.types.Scene.vernacular = bpy.props.PointerProperty(type=VernacularSettings)
    if not bpy.app.timers.is_registered(watch_grammars):
        bpy.app.timers.register(watch_grammars, first_interval=0.5, persistent=True)


def unregister():
    if bpy.app.timers.is_registered(watch_grammars):
        bpy.app.timers.unregister(watch_grammars)
    del bpy.types.Scene.vernacular
    for c in reversed(_classes):
        bpy.utils.unregister_class(c)
