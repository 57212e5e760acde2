"""An operation's own object is its own, never another clause's item: in an office whose
shredder takes its one personal paper ("paperwork": a form, an invoice, a job sheet),
"Shred my old alarm code sheet, and bring me a coffee" had shredded the coffee ("Sorry, I can't
shred a coffee here"). An ordinary English head of a paper document ("sheet", "notes",
"printout", ``document_heads``) after "my" and any modifiers, the object of an operation whose
input is the office's one personal paper, is that paper, the requester's own
(``reading.own_papers``); an object no word of the office names is asked, never borrowed from a
thing another clause asks for (``frames._named_elsewhere``)."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office
from helpers import office_builder as ob


def _raw() -> ob.Row:
    return ob.office_file(
        "shred and coffee",
        (
            ob.person("lee", "Lee Hart", "paperwork", "stapler"),
            ob.person("rosa", "Rosa Quint", "paperwork"),
            ob.person("tom", "Tom Brady"),
        ),
        rooms=[
            ob.room("back_room", "Back room", 4.0, 20.0),
            ob.room("kitchen", "Kitchen", 12.0, 20.0),
        ],
        item_types=[
            ob.item(
                "paperwork",
                "paperwork",
                "personal",
                synonyms=["form", "invoice", "job sheet"],
                signable=True,
            ),
            ob.item("stapler", "stapler"),
            ob.item("coffee", "coffee", "product", synonyms=["latte"]),
        ],
        operations=[
            ob.operation("shred", "shred", name="shred", input="paperwork"),
            ob.operation("brew", "make", "brew", name="make coffee", product="coffee"),
        ],
        facilities=[
            ob.facility(
                "shredder", "shredder", at="back_room", guards=["tom"], operations=["shred"]
            ),
            ob.facility(
                "coffee_machine",
                "coffee machine",
                at="kitchen",
                guards=[],
                operations=["brew"],
                products=["coffee"],
            ),
        ],
        home="back_room",
    )


_office = ob.parsed(_raw)


@functools.cache
def _parser() -> InstructionParser:
    office: Office = _office()
    return InstructionParser(office)


def _tasks(text: str) -> list[tuple[str, str | None, str | None]]:
    frame = _parser().parse(text, "lee")
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.owner) for t in frame.tasks]


_SHRED = ("heat", "paperwork", "lee")
_COFFEE = ("produce", "coffee", None)


@pytest.mark.parametrize(
    "text",
    [
        "Shred my old alarm code sheet, and bring me a coffee while you're at it",
        "Shred my old alarm code sheet, then make me a coffee",
        "Shred my old alarm code sheet. Bring me a coffee.",
    ],
)
def test_the_sheet_is_shredded_and_the_coffee_brought(text: str) -> None:
    assert sorted(_tasks(text), key=str) == sorted([_SHRED, _COFFEE], key=str)


@pytest.mark.parametrize(
    "text", ["Shred my old alarm code sheet", "shred my meeting notes", "shred my old printout"]
)
def test_a_paper_head_alone_is_the_requesters_paperwork(text: str) -> None:
    assert _tasks(text) == [_SHRED]


@pytest.mark.parametrize(
    "text",
    [
        "Shred my old alarm code thingy, and bring me a coffee",
        "shred my old alarm code thingy and bring me a stapler",
    ],
)
def test_an_unnamed_object_is_asked_never_borrowed(text: str) -> None:
    frame = _parser().parse(text, "lee")
    assert frame.decline is None and frame.tasks == []
    assert frame.question == "Which item do you mean for me to shred?"


def test_neighbour_paperwork_and_a_coffee_two_tasks() -> None:
    assert sorted(_tasks("shred my paperwork and bring me a coffee"), key=str) == sorted(
        [_SHRED, _COFFEE], key=str
    )


def test_neighbour_shredding_my_coffee_is_no_paperwork() -> None:
    frame = _parser().parse("shred my coffee", "lee")
    assert not any(t.item == "paperwork" for t in frame.tasks)


def test_neighbour_a_paper_head_with_another_verb_is_not_guessed() -> None:
    # "bring" takes no paperwork: "my old sheet" is not read as the requester's paperwork
    frame = _parser().parse("bring me my old sheet", "lee")
    assert not any(t.item == "paperwork" for t in frame.tasks)
