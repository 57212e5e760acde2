"""A small architecture studio with two facilities that print: an A3 printer that prints and
a plotter that makes large-format plots, for the reader's tests of a size or format word
choosing between them (reading/size_words.py). No sentence or name of a measured office is
in it."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("tove", "Tove Lind"),
    ob.person("femi", "Femi Ade"),
    ob.person("juno", "Juno Park"),
)


def raw_plan_room() -> dict[str, Any]:
    return ob.office_file(
        "plan room",
        _PEOPLE,
        rooms=[
            ob.room("print_bay", "Print bay", 4.0, 20.0),
            ob.room("plot_room", "Plot room", 12.0, 20.0),
        ],
        item_types=[
            ob.item(
                "drawing",
                "drawing",
                "electronic",
                synonyms=["plans", "poster", "drawings", "elevations"],
            ),
            ob.item("printout", "printout", "product"),
            ob.item("plot", "plot", "product", synonyms=["large print"]),
        ],
        operations=[
            ob.operation("print", "print", input="drawing", product="printout"),
            ob.operation("plot", "plot", name="large-format plot", input="drawing", product="plot"),
        ],
        facilities=[
            ob.facility(
                "a3_printer",
                "A3 printer",
                at="print_bay",
                guards=["femi"],
                operations=["print"],
                products=["printout"],
                synonyms=["printer"],
            ),
            ob.facility(
                "plotter",
                "plotter",
                at="plot_room",
                guards=["juno"],
                operations=["plot"],
                products=["plot"],
                synonyms=["large format printer", "A0 plotter"],
            ),
        ],
        everyone_owns=["drawing"],
        home="print_bay",
    )


plan_room = ob.parsed(raw_plan_room)


def raw_shared_verb_plan_room() -> dict[str, Any]:
    """The studio whose plotter is asked for by "print" too (its verbs "plot", "print")."""
    raw = raw_plan_room()
    plot = next(op for op in raw["operations"] if op["id"] == "plot")
    plot["verbs"] = ["plot", "print"]
    return raw


shared_verb_plan_room = ob.parsed(raw_shared_verb_plan_room)
