"""Vernacular: example buildings into a grammar of their style, and the
grammar into new buildings in that style.

    import vernacular
    examples = vernacular.read_examples(["data/examples/garage"])
    style = vernacular.infer(examples)
    style.save("garage.grm")
    houses = vernacular.derive_many(style.grammar, 10)
    vernacular.write_buildings(houses, style.grammar, "houses.glb")

Every failure is a vernacular.Error (a subclass by its kind) carrying
kind, file, line, column, message and hint.
"""

from . import _vernacular
from ._vernacular import (Building, Example, Grammar, InferResult, Verdict, __version__, check, derive,
                          derive_many, infer, read_examples, shard, write_buildings)


class Error(Exception):
    """A failure: kind ('usage', 'input', 'limit', 'io', 'internal'), where
    (file, line, column; empty and 0 where unknown), message and hint."""
    kind = "internal"
    file = ""
    line = 0
    column = 0
    message = ""
    hint = ""


class UsageError(Error):
    """A call's arguments are wrong."""


class InputError(Error):
    """A grammar or example file is wrong."""


class LimitError(Error):
    """A limit was reached (depth, parts, matching steps, memory)."""


class IoError(Error):
    """A file could not be read or written."""


class InternalError(Error):
    """A bug in Vernacular: please report it."""


_vernacular._set_errors({"usage": UsageError, "input": InputError, "limit": LimitError, "io": IoError,
                         "internal": InternalError})

__all__ = ["Building", "Error", "Example", "Grammar", "InferResult", "InputError", "InternalError", "IoError",
           "LimitError", "UsageError", "Verdict", "__version__", "check", "derive", "derive_many", "infer",
           "read_examples", "shard", "write_buildings"]
