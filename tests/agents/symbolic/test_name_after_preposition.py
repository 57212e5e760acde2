"""A colleague's name right after a preposition ("both for Rose", "for Drew") is the
preposition's object, never a statement's past verb ("rose" of "rise", "drew" of "draw"):
"print my file and a tea, both for Rose" asks for both things for Rose, where the piece
"both for Rose" was set aside as a statement and both went to the requester
(``speech.statement``). A verb that names nobody after no preposition is still a verb."""

from __future__ import annotations

from typing import Any

import pytest

from helpers import office_builder as ob
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader

_HARBOUR = frame_reader(harbour_office, "will")


def _raw_studio() -> dict[str, Any]:
    """A small studio where a colleague's name is a past verb ("Drew")."""
    return ob.office_file(
        "studio",
        (ob.person("ana", "Ana Reyes"), ob.person("drew", "Drew Hale")),
        everyone_owns=["file"],
        rooms=[ob.room("print_room", "Print room", 4.0, 18.0)],
        item_types=[
            ob.item("file", "electronic file", "electronic", synonyms=["file"]),
            ob.item("printout", "printout", "product", synonyms=["print"]),
            ob.item("tea", "tea", "product"),
        ],
        operations=[
            ob.operation("print", "print", input="file", product="printout"),
            ob.operation("brew", "make", "brew", product="tea"),
        ],
        facilities=[
            ob.facility(
                "printer", "printer", at="print_room", guards=["ana"], operations=["print"]
            ),
            ob.facility("kettle", "kettle", at="print_room", guards=["ana"], operations=["brew"]),
        ],
        home="print_room",
    )


_STUDIO = frame_reader(ob.parsed(_raw_studio), "ana")


@pytest.mark.parametrize(
    ("text", "name"),
    [
        ("print my file and a tea, both for Rose", "Rose Adeyemi"),  # the brief's check
        ("print my file and a tea, all for Rose", "Rose Adeyemi"),
        ("print my file and a tea, both for Mark", "Mark Lindqvist"),  # as before
    ],
)
def test_harbour_both_parts_go_to_the_name(text: str, name: str) -> None:
    frame = _HARBOUR(text)
    assert frame.question is not None, frame  # restated, as a made-from-nothing part is
    assert frame.question.count(f"for {name}") == 2, frame
    assert "for you" not in frame.question, frame


def test_a_name_that_is_a_past_verb_in_a_small_office() -> None:
    frame = _STUDIO("print my file and a tea, both for Drew")
    assert frame.question is not None, frame
    assert frame.question.count("for Drew Hale") == 2, frame


def test_a_past_verb_naming_nobody_is_still_told() -> None:
    """Neighbour: "the kite rose to the roof" names no one after a preposition: a statement,
    nothing asked, as before."""
    frame = _HARBOUR("the kite rose to the roof")
    assert frame.tasks == [], frame
    assert any("statement" in e.meaning for e in frame.evidence), frame
