#!/usr/bin/env python3
"""Writes the seed corpus of the fuzz targets into fuzz/corpus/<target>/.

    python3 fuzz/make_seed_corpus.py [path/to/generate]   (default build/bin/generate)

Seeds are small on purpose (a fuzzer mutates every byte of them): the
bundled grammars, the primitives and the smallest example of each style,
glTF/GLB files that `generate` writes for a few tiny grammars, hand-written
glTF files that use what `generate` never writes (strips, fans, matrices,
8-bit indices, no scene), example layouts in the byte format of
fuzz/entries/layout.hpp, and folder trees in the text format of
fuzz/entries/folder_tree.hpp. The output is the same every run.
"""
import base64
import json
import shutil
import struct
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT / "fuzz" / "corpus"


def fresh(target):
    folder = CORPUS / target
    if folder.exists():
        shutil.rmtree(folder)
    folder.mkdir(parents=True)
    return folder


def grammar_seeds():
    out = fresh("grammar_reader")
    for f in sorted((ROOT / "data" / "grammars").glob("*.grm")) + [ROOT / "tests" / "data" / "every_operation.grm"]:
        shutil.copy(f, out / f.name)
    # Every expression form and function once, in small grammars.
    small = {
        "expressions.grm": "@start p\n@scope 4, 2 * 3, rand(5, 7)\nk = randint(1, 3) % 2 + -1\n"
        "p --> split(y){ ~normal(1, 0.1) : q(k, x) | tnormal(1, 1, 0, 2) : nil | ~choice(1, 2, 3) : I(a) }\n"
        "q(n, ax) : n >= 1 && !(n == 2) || n != 3 --> repeatN(ax, max(1, min(n, 4))){ I(b) }\n"
        "q(n, ax) : abs(n) < floor(2.5) --> repeat(ax){ ceil(round(sqrt(2))) : S(~1, 0.5, ~1){ I(c) } }\n"
        "q(n, ax) --> T(sin(pi), cos(0), 1 / 2){ R(z, pi / 2){ I(d) } } : 0.5\n"
        "q(n, ax) --> split(ax){ size(ax) / 4 : I(e) | ~size(z) : nil } : 0.25\n",
        "comp.grm": "p --> comp(f){ top : colour(red) | bottom : colour(0.2, 0.4, 0.6) | front : nil"
        " | back : I(w) | left : I(x1) | right : color(blue) }\n",
        "arrows.grm": "// other arrows\na -> b\nb → split(0){ 1 : I(r) | ~1 : c }\nc --> I(r)\n",
        "recursion.grm": "f(n) : n > 0 --> split(z){ ~1 : I(a) | ~n : f(n - 1) }\nf(n) --> nil\nstart --> f(5)\n@start start\n",
        "primitives.grm": '@primitives "style.prims.obj"\np --> I(window)\n',
    }
    for name, text in small.items():
        (out / name).write_text(text)


def obj_seeds():
    out = fresh("obj_loader")
    for f in sorted((ROOT / "data" / "primitives").glob("*.obj")):
        shutil.copy(f, out / f.name)
    for style in ("garage", "better_roofs"):
        shutil.copy(ROOT / "data" / "examples" / style / "variant_000.obj", out / f"{style}_000.obj")
    small = {
        "negative_indices.obj": "o wall.001\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4 -3 -2 -1\n"
        "o wall.002\nv 0 0 1\nv 1 0 1\nv 1 1 2\nf -3 -2 -1\n",
        "corner_forms.obj": "mtllib x.mtl\ng door\nv 0 0 0 1\nv 2 0 0 0.5 0.5 0.5\nv 2 0 3\nvt 0 0\nvt 1 0 0\nvn 0 -1 0\n"
        "usemtl m\ns off\nf 1/1/1 2/2/1 3//1\nf 1/1 2/2 3/1\nl 1 2\n",
        "continuation.obj": "# a line continued\no roof\nv 0 0 0\nv 1 \\\n 0 0\nv 0 1 1\nf 1 2 \\\n3\n",
        "unnamed.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        "names.obj": "o window.001\nv 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\no window.002 # a comment\n"
        "v 2 0 0\nv 3 0 0\nv 2 0 1\nf 4 5 6\no .001\nv 0 2 0\nv 1 2 0\nv 0 2 1\nf 7 8 9\n",
        "point.obj": "o dot\nv 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n",
        "up_declared.obj": "# Written by Vernacular\n# up y\no wall\nv 0 0 0\nv 1 0 -1\nv 0 1 0\nvn 0 1 0\nf 1//1 2//1 3//1\n",
    }
    for name, text in small.items():
        (out / name).write_text(text)


def gltf_seeds(generate):
    out = fresh("gltf_loader")
    grammars = {
        "one_box": "p --> I(rect)\n",
        "two_parts": "@scope 4, 2, 3\np --> split(x){ ~1 : I(rect) | ~1 : R(z, pi / 2){ I(roof) } }\n",
        "garage": (ROOT / "data" / "grammars" / "garage.grm").read_text(),
    }
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in grammars.items():
            grm = Path(tmp) / f"{name}.grm"
            grm.write_text(text)
            for ext in ("glb", "gltf"):
                subprocess.run([generate, str(grm), "-n", "1", "-q", "-o", str(out / f"{name}.{ext}")], check=True)

    # Hand-written: a triangle strip and fan with 8-bit indices, a node
    # matrix, a child node, no "scenes" (roots are the nodes no one lists).
    positions = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 1)
    indices = bytes([0, 1, 2, 3])
    blob = positions + indices
    uri = "data:application/octet-stream;base64," + base64.b64encode(blob).decode()
    model = {
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": len(blob), "uri": uri}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 4}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 1]},
                      {"bufferView": 1, "componentType": 5121, "count": 4, "type": "SCALAR"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 5}]},
                   {"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 6}]},
                   {"primitives": [{"attributes": {"POSITION": 0}, "mode": 0}]}],
        "nodes": [{"name": "wall.001", "mesh": 0, "children": [1],
                   "matrix": [2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1]},
                  {"name": "roof", "mesh": 1, "translation": [0, 0, 1], "rotation": [0, 0, 0.7071068, 0.7071068],
                   "scale": [1, 2, 1]},
                  {"name": "points", "mesh": 2}],
    }
    (out / "strip_fan_matrix.gltf").write_text(json.dumps(model, indent=1))
    # The same as GLB, the buffer in the binary chunk.
    model_bin = json.loads(json.dumps(model))
    del model_bin["buffers"][0]["uri"]
    js = json.dumps(model_bin, separators=(",", ":")).encode()
    js += b" " * (-len(js) % 4)
    binary = blob + b"\0" * (-len(blob) % 4)
    glb = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(js) + 8 + len(binary))
    glb += struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(binary), b"BIN\0") + binary
    (out / "strip_fan_matrix.glb").write_bytes(glb)


def layout_seeds():
    out = fresh("infer_layout")
    # Bytes as fuzz/entries/layout.hpp reads them.
    seeds = {
        # One tree: 4 x 1 x 2 cut along x into a | empty | b.
        "cut_three.bin": [0x00, 0x01, 3, 0, 1, 0x1A, 0, 1, 0, 0x00, 0x01, 0x04],
        # A facade: floors along z, each cut along x into window | wall | window.
        "facade.bin": [0x00, 0x01, 9, 0, 8, 0x2A, 1, 1, 1, 0x1E, 0, 1, 0, 0x04, 0x08, 0x04,
                       0x1E, 0, 1, 0, 0x04, 0x08, 0x04, 0x1E, 0, 1, 0, 0x04, 0x08, 0x04],
        # Two examples of one style, 0.1 m grid, 32-bit floats, moved off the origin.
        "two_examples.bin": [0x6D, 0x01, 5, 3, 7, 0x2A, 1, 0, 1, 0x00, 0x1A, 0, 1, 0, 0x04, 0x01, 0x04, 0x08,
                             0x01, 7, 3, 7, 0x2A, 1, 2, 1, 0x00, 0x1A, 0, 1, 0, 0x04, 0x01, 0x04, 0x08],
        # Three examples, unit 3.
        "three_examples.bin": [0x12, 0x01, 2, 2, 2, 0x00, 0x01, 4, 2, 2, 0x1A, 0, 0, 0, 0x00, 0x01, 0x00,
                               0x01, 6, 2, 2, 0x1A, 0, 0, 0, 0x00, 0x01, 0x00],
        # Free boxes: two touching, one flat panel on a face, a gap.
        "free_boxes.bin": [0x00, 0x06, 0, 0, 0, 0, 2, 2, 2, 1, 2, 0, 0, 2, 2, 2, 2, 6, 0, 0, 1, 2, 0, 2],
        # Free boxes that overlap (an Input error).
        "overlap.bin": [0x00, 0x02, 0, 0, 0, 0, 4, 4, 4, 1, 1, 1, 1, 4, 4, 4],
        # A pinwheel of five boxes that no straight cut divides.
        "pinwheel.bin": [0x00, 0x08, 0, 0, 0, 0, 2, 1, 1, 1, 2, 0, 0, 1, 2, 1, 2, 1, 2, 0, 2, 1, 1,
                         3, 0, 1, 0, 1, 2, 1, 4, 1, 1, 0, 1, 1, 1],
        # Millimetre and kilometre grids.
        "tiny_unit.bin": [0x14, 0x01, 3, 3, 3, 0x02, 0, 0, 0x05, 0x09],
        "huge_unit.bin": [0x18, 0x01, 3, 3, 3, 0x3E, 0, 3, 1, 2, 0x04, 0x01, 0x08, 0x0C],
        # A cut tree 258 deep: 257 slabs peeled off the rest along x, y, z
        # in turn, labels a to f, then the core.
        "peeled.bin": [0x00, 0xC1, 0] + [(i % 3) | ((i % 6) << 2) for i in range(257)] + [0],
    }
    for name, data in seeds.items():
        (out / name).write_bytes(bytes(data))


def indirect_seeds():
    out = fresh("indirect_inputs")
    # Text as fuzz/entries/folder_tree.hpp reads it: a header line, then
    # "@@ main", "@@ file NAME", "@@ repeat NAME COUNT", "@@ link NAME
    # TARGET" and "@@ dir NAME" sections. One triangle, 36 bytes of floats.
    triangle = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 1)

    def gltf(uri, images=()):
        model = {
            "asset": {"version": "2.0"},
            "buffers": [{"byteLength": len(triangle), "uri": uri}],
            "bufferViews": [{"buffer": 0, "byteLength": len(triangle)}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                           "min": [0, 0, 0], "max": [1, 1, 1]}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
            "nodes": [{"name": "wall", "mesh": 0}],
        }
        if images:
            model["images"] = [{"uri": u} for u in images]
        return json.dumps(model, separators=(",", ":")).encode()

    def glb(uri):
        js = gltf(uri)
        js += b" " * (-len(js) % 4)
        return struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(js)) + struct.pack("<I4s", len(js), b"JSON") + js

    def tree(header, main, *sections):
        text = header.encode() + b"\n@@ main\n" + main
        for head, data in sections:
            text += b"\n@@ " + head.encode() + b"\n" + data
        return text

    door = b"o door\nv 0 0 0\nv 1 0 0\nv 1 2 0\nv 0 2 0\nf 1 2 3 4\n"
    window = b"o window.001\nv 0 0 0\nv 1 0 0\nv 0 1 1\nf 1 2 3\n"
    seeds = {
        # A buffer beside the glTF, one in a subfolder with a percent-encoded name.
        "gltf_beside.txt": tree("", gltf("wall.bin"), ("file wall.bin", triangle)),
        "gltf_subfolder_percent.txt": tree("", gltf("parts/wall%20one.bin"), ("file parts/wall%20one.bin", triangle)),
        # A buffer above the glTF's folder: refused, then allowed.
        "gltf_parent_step.txt": tree("", gltf("../wall.bin"), ("file ../wall.bin", triangle)),
        "gltf_parent_step_allowed.txt": tree("outside", gltf("../wall.bin"), ("file ../wall.bin", triangle)),
        "gltf_encoded_parent_step.txt": tree("", gltf("%2e%2e/wall.bin"), ("file ../wall.bin", triangle)),
        # Links that lead out: a file's, a folder's.
        "gltf_link_out.txt": tree("", gltf("wall.bin"), ("file ../outside/wall.bin", triangle),
                                  ("link wall.bin ../outside/wall.bin", b"")),
        "gltf_folder_link_out.txt": tree("", gltf("parts/wall.bin"), ("file ../outside/wall.bin", triangle),
                                         ("link parts ../outside", b"")),
        # Absolute paths, allowed.
        "gltf_absolute_allowed.txt": tree("outside", gltf("$ROOT/outside/wall.bin"),
                                          ("file ../outside/wall.bin", triangle)),
        # Images: the glTF itself, a missing one; the buffer a data: URI.
        "gltf_images.txt": tree("", gltf("data:application/octet-stream;base64," + base64.b64encode(triangle).decode(),
                                         images=("main.gltf", "missing.png", "sub/../main.gltf"))),
        # A buffer file longer than its byteLength.
        "gltf_repeat_mismatch.txt": tree("", gltf("big.bin"), ("repeat big.bin 4096", triangle)),
        # A GLB whose buffer is a file beside it.
        "glb_external_buffer.txt": tree("", glb("wall.bin"), ("file wall.bin", triangle)),
        # A grammar's @primitives: a file, a folder with a link out, a file
        # outside (allowed), a folder link out, an absolute path, itself.
        "grammar_file.txt": tree("grammar", b'@primitives "style.prims.obj"\np --> I(door)\n',
                                 ("file style.prims.obj", door + window)),
        "grammar_folder_links.txt": tree("grammar", b'@primitives "prims"\np --> I(window)\n',
                                         ("dir prims", b""), ("file prims/window.obj", window),
                                         ("file ../door.obj", door), ("link prims/door.obj ../../door.obj", b"")),
        "grammar_outside_allowed.txt": tree("grammar outside", b'@primitives "../shared/prims.obj"\np --> I(door)\n',
                                            ("file ../shared/prims.obj", door)),
        "grammar_folder_link_out.txt": tree("grammar", b'@primitives "prims"\np --> I(door)\n',
                                            ("file ../shared/door.obj", door), ("link prims ../shared", b"")),
        "grammar_absolute.txt": tree("grammar", b'@primitives "$ROOT/shared/door.obj"\np --> I(door)\n',
                                     ("file ../shared/door.obj", door)),
        "grammar_self.txt": tree("grammar", b'@primitives "main.grm"\np --> I(door)\n'),
    }
    for name, data in seeds.items():
        (out / name).write_bytes(data)


def main():
    generate = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "build" / "bin" / "generate")
    grammar_seeds()
    obj_seeds()
    gltf_seeds(generate)
    layout_seeds()
    indirect_seeds()
    for target in sorted(p.name for p in CORPUS.iterdir()):
        files = list((CORPUS / target).iterdir())
        print(f"{target}: {len(files)} seeds, {sum(f.stat().st_size for f in files)} bytes")


if __name__ == "__main__":
    main()
