"""A kind of machine the office lacks, named by a word before the office's own machine word,
is never run on the office's one (fixer 60e class 1; the round's offices and sentences were
never read). "fire my pot in the raku kiln" where the pottery has one plain kiln asks
("There's no raku kiln here, only the kiln. Shall I use the kiln instead?"); a yes fires it in
the kiln, a no does nothing. A word of the kiln's own names, an adjective, a word of which one
("the office printer"), a room of the office, a possessive and words after the name read as
before."""

from __future__ import annotations

from typing import Any

import pytest

from helpers import office_builder as ob
from helpers.dataset_offices import default_office
from helpers.reading import answered_reader, frame_reader


def _raw_pottery() -> dict[str, Any]:
    return ob.office_file(
        "pottery",
        (
            ob.person("ana", "Ana Lund", "pot"),
            ob.person("tom", "Tom Reyes", "pot"),
        ),
        rooms=[
            ob.room("kiln_room", "Kiln room", 6.0, 18.0),
            ob.room("studio", "Studio", 14.0, 18.0),
        ],
        item_types=[ob.item("pot", "pot", synonyms=["jug"])],
        operations=[ob.operation("fire", "fire", "bake", input="pot")],
        facilities=[
            ob.facility(
                "kiln",
                "kiln",
                at="kiln_room",
                guards=["ana"],
                operations=["fire"],
                synonyms=["electric kiln"],
            )
        ],
        home="studio",
        group=("staff", "Staff"),
    )


_pottery = ob.parsed(_raw_pottery)
_frame = answered_reader(_pottery, "tom")
_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "asked"),
    [
        ("can you put my jug in the raku kiln this afternoon", "raku kiln"),
        ("fire my pot in the gas kiln", "gas kiln"),
        ("could you stick my pot in the wood-fired kiln tomorrow?", "wood-fired kiln"),
    ],
)
def test_a_kind_of_kiln_the_office_lacks_is_asked_about(text: str, asked: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.question is not None and asked in frame.question
    assert "only the kiln" in frame.question


def test_a_yes_fires_it_in_the_kiln_and_a_no_does_nothing() -> None:
    text = "fire my pot in the raku kiln"
    yes = _frame(text, ("yes",))
    assert len(yes.tasks) == 1 and yes.tasks[0].item == "pot"
    no = _frame(text, ("no thanks",))
    assert no.tasks == []


@pytest.mark.parametrize(
    "text",
    [
        "fire my pot in the kiln",
        "fire my pot in the big kiln",
        "fire my pot in the big electric kiln",
        "fire my pot in the new kiln",
        "fire my pot in the usual kiln",
        "fire my pot in the studio kiln",
        "fire my pot in the kiln downstairs",
        "fire my pot in the kiln please",
    ],
)
def test_the_kilns_own_words_and_qualities_fire_as_before(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None
    assert len(frame.tasks) == 1 and frame.tasks[0].item == "pot"


@pytest.mark.parametrize(
    "text",
    ["heat my lunch in the gas microwave", "print my report on the A3 printer"],
)
def test_a_kind_of_the_default_offices_machine_is_asked_about(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.question is not None
    assert "Shall I use the" in frame.question


def test_the_machine_is_named_as_it_was_asked_for() -> None:
    """The office calls its microwave an oven too: "the pizza oven" is said back as asked,
    never "pizza microwave", a machine nobody named."""
    frame = _default("heat my lunch in the pizza oven")
    assert frame.question is not None
    assert frame.question.startswith("There's no pizza oven here, only the microwave.")


@pytest.mark.parametrize(
    "text",
    [
        "print my report on the big printer",
        "print my report on the office printer",
        "print my report on the new printer",
        "print my report on the printer downstairs",
        "heat my lunch in the kitchen microwave",
        "get me some printer paper",
    ],
)
def test_which_printer_or_microwave_reads_as_before(text: str) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None
    assert len(frame.tasks) == 1
