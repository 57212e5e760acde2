"""A small design studio for the reader's tests of combinations of two requests, unlisted
everyday paper nouns ("my report", "my memo") and answers that keep what the request said:
the personal paper is a "document" with other synonyms, the electronic one a "file", a charger
and a stapler several people own, a kettle that makes tea, a printer that prints a file, and a
colleague with a title for an alias ("the Boss")."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("nina", "Nina Holt", "charger", "stapler"),
    ob.person("olive", "Olive Brand", "charger"),
    ob.person("brook", "Brook Tamsin", "charger", aliases=["Brook"]),
    ob.person("fiona", "Fiona Marsh", "stapler"),
    ob.person("dora", "Dora Quill", "stapler", aliases=["the Boss", "Boss"]),
)


def raw_design_studio() -> dict[str, Any]:
    return ob.office_file(
        "design studio",
        _PEOPLE,
        rooms=[
            ob.room("galley", "Galley", 4.0, 20.0),
            ob.room("copy_room", "Copy room", 12.0, 20.0),
        ],
        item_types=[
            ob.item(
                "document", "document", "personal", signable=True, synonyms=["form", "contract"]
            ),
            ob.item("file", "electronic file", "electronic", synonyms=["file", "pdf"]),
            ob.item("charger", "charger", synonyms=["phone charger"]),
            ob.item("stapler", "stapler"),
            ob.item("tea", "tea", "product", synonyms=["cup of tea", "cuppa", "brew"]),
            ob.item("printout", "printout", "product", synonyms=["print"]),
        ],
        operations=[
            ob.operation("make_tea", "make", name="make tea", product="tea"),
            ob.operation("print", "print", input="file", product="printout"),
        ],
        facilities=[
            ob.facility("kettle", "kettle", at="galley", guards=["olive"], operations=["make_tea"]),
            ob.facility(
                "printer", "printer", at="copy_room", guards=["fiona"], operations=["print"]
            ),
        ],
        everyone_owns=["document", "file"],
        home="galley",
    )


design_studio = ob.parsed(raw_design_studio)


def raw_two_papers_studio() -> dict[str, Any]:
    """The studio with a second personal paper (a "ticket" named by no paper noun, and a
    "certificate" that is signed): "my memo" may be either, so it is asked about."""
    raw = raw_design_studio()
    raw["item_types"].append(ob.item("certificate", "certificate", "personal", signable=True))
    for p in raw["people"]:
        p["owns"].append({"type": "certificate"})
    return raw


two_papers_studio = ob.parsed(raw_two_papers_studio)
