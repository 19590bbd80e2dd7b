"""The Python module vernacular (python/), run by pytest from CTest with
the build's module first on PYTHONPATH."""

import os
import pathlib

import numpy
import pytest

import vernacular

SOURCE = pathlib.Path(os.environ.get("VERN_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
GARAGE = SOURCE / "data" / "examples" / "garage"


def test_the_garages_style_derives_every_garage_and_new_ones(tmp_path):
    examples = vernacular.read_examples([str(GARAGE)])
    assert len(examples) == len(list(GARAGE.glob("*.obj")))
    style = vernacular.infer(examples)
    assert style.examples == len(examples)
    for e in examples:
        verdict = vernacular.check(style.grammar, e)
        assert verdict.derivable, (e.source, verdict.reason)
        assert verdict.witness
    style.save(str(tmp_path / "garage.grm"))
    assert (tmp_path / "garage.prims.obj").exists()
    grammar = vernacular.Grammar.read(str(tmp_path / "garage.grm"))
    assert grammar.text() == vernacular.Grammar.parse(grammar.text()).text()
    variants = vernacular.derive_many(grammar, 4, seed=11)
    assert len(variants) == 4
    for i, b in enumerate(variants):
        again = vernacular.derive(grammar, seed=11 + i)
        assert numpy.array_equal(again.parts["origins"], b.parts["origins"])
    vernacular.write_buildings(variants, grammar, str(tmp_path / "variants.glb"))
    assert (tmp_path / "variants.glb").read_bytes()[:4] == b"glTF"
    back = vernacular.read_examples([str(tmp_path / "variants.glb")])
    assert len(back) == 4
    assert all(vernacular.check(grammar, e) for e in back)


def test_parts_are_arrays_a_row_per_part():
    grammar = vernacular.Grammar.parse("house --> split(z){ 3 : I(wall) | ~1 : I(roof) }\n")
    b = vernacular.derive(grammar, plot=(6.0, 4.0, 9.0))
    parts = b.parts
    assert len(b) == 2
    assert list(parts["labels"]) == ["wall", "roof"]
    assert parts["origins"].shape == (2, 3) and parts["sizes"].shape == (2, 3)
    assert parts["axes"].shape == (2, 3, 3)
    numpy.testing.assert_allclose(parts["sizes"], [[6, 4, 3], [6, 4, 6]])
    numpy.testing.assert_allclose(parts["origins"][1], [0, 0, 3])
    numpy.testing.assert_allclose(parts["axes"][0], numpy.eye(3))
    assert tuple(b.plot) == (6.0, 4.0, 9.0)


def test_a_broken_grammar_raises_an_input_error_at_its_line_and_column():
    with pytest.raises(vernacular.InputError) as caught:
        vernacular.Grammar.parse("house --> split(z){ 3 : wall | ~1 : I(roof) }\n", name="house.grm")
    e = caught.value
    assert isinstance(e, vernacular.Error)
    assert e.kind == "input"
    assert e.file == "house.grm"
    assert e.line == 1 and e.column > 0
    assert "wall" in e.message
    assert str(e).startswith("house.grm:1:")


def test_wrong_arguments_and_missing_files_raise_their_kinds(tmp_path):
    with pytest.raises(vernacular.UsageError) as caught:
        vernacular.infer([])
    assert caught.value.hint
    with pytest.raises(vernacular.UsageError):
        vernacular.read_examples([str(GARAGE)], buildings="rows")
    with pytest.raises(vernacular.IoError) as missing:
        vernacular.Grammar.read(str(tmp_path / "none.grm"))
    assert "none.grm" in str(missing.value)
    with pytest.raises(vernacular.LimitError):
        vernacular.derive(vernacular.Grammar.parse("a --> split(x){ ~1 : a | ~1 : a }\n"), max_depth=10)


def test_the_version_is_the_packages():
    assert vernacular.__version__.count(".") == 2


def test_an_example_made_from_boxes_infers_as_a_file_would():
    examples = []
    for width in (6.0, 8.0, 10.0):
        boxes = numpy.array([[[0, 0, 0], [width, 4, 2.7]], [[0, 0, 2.7], [width, 4, 3.9]]])
        examples.append(vernacular.Example.from_boxes(["wall", "roof"], boxes, source=f"house_{width:g}"))
    assert examples[0].source == "house_6" and examples[0].labels == ["wall", "roof"]
    numpy.testing.assert_allclose(examples[2].boxes[1], [[0, 0, 2.7], [10, 4, 3.9]])
    style = vernacular.infer(examples)
    assert all(vernacular.check(style.grammar, e) for e in examples)
    with pytest.raises(vernacular.UsageError):
        vernacular.Example.from_boxes(["wall"], numpy.zeros((2, 2, 3)))
    with pytest.raises(vernacular.InputError):
        vernacular.Example.from_boxes(["wall"], numpy.array([[[0, 0, 0], [-1, 1, 1]]]), source="mine")
