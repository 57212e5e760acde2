"""A slip in one word of a thing's name of several words ("blu tac" for blu tack, "gaffa tap"
for gaffa tape): the office's own names (and synonyms) of several words are matched as phrases,
all words but one said exactly and the one left a letter short, over or swapped
(``reading.phrase_typos``); before, a word under four letters or an English word ("tap") was
never corrected and the thing was declined as unknown. A letter changed for another counts only
beside a word English rarely uses; two ordinary words ("paper cut") stay English."""

from __future__ import annotations

from typing import Any

import pytest
from _offices import tasks_of

from assistantx.agents.symbolic import InstructionParser
from helpers import office_builder as ob


def _raw_print_shop() -> dict[str, Any]:
    people = (
        ob.person("ines", "Ines Ford", "pen"),
        ob.person("rui", "Rui Costa", "pen"),
    )
    return ob.office_file(
        "print shop",
        people,
        rooms=[ob.room("store", "Store cupboard", 20.0, 20.0)],
        item_types=[
            ob.item("pen", "pen"),
            ob.item("blu_tack", "blu tack", synonyms=["sticky putty"], mass=True),
            ob.item("gaffa_tape", "gaffa tape", synonyms=["duct tape"], mass=True),
            ob.item("sticky_tape", "sticky tape", mass=True),
            ob.item("paper_cup", "paper cup"),
        ],
        operations=[],
        facilities=[
            ob.facility(
                "cupboard",
                "cupboard",
                at="store",
                guards=["rui"],
                supplies=["blu_tack", "gaffa_tape", "sticky_tape", "paper_cup"],
            ),
        ],
        home="store",
    )


_print_shop = ob.parsed(_raw_print_shop)


def _items(text: str) -> list[str | None]:
    frame = InstructionParser(_print_shop()).parse(text, "ines")
    assert frame.question is None and frame.decline is None, frame
    return [t.item for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "item"),
    [
        # the class's analogues
        ("could you bring me some blu tac from the cupboard", "blu_tack"),
        ("bring me gaffa tap please", "gaffa_tape"),
        # variants: the first word, a swap, a letter changed beside a rare word, a synonym
        ("can I get some blue tack", "blu_tack"),
        ("grab me the stikcy tape", "sticky_tape"),
        ("bring me some gaffa tapr", "gaffa_tape"),
        ("could I have some sticky puty", "blu_tack"),
    ],
)
def test_the_names_word_typed_with_a_slip(text: str, item: str) -> None:
    assert _items(text) == [item]


@pytest.mark.parametrize(
    ("office", "requester", "text", "item"),
    [
        ("harbour", "may", "bring me some scotch tap", "tape"),
        ("harbour", "may", "could you get me some sticky tap", "tape"),
        ("default", "mao", "could you bring me the company sea", "seal"),
    ],
)
def test_on_the_dataset_offices(office: str, requester: str, text: str, item: str) -> None:
    assert [task[1] for task in tasks_of(office, text, requester)] == [item]


def test_two_ordinary_words_stay_english() -> None:
    """Must not change: "paper cut" is a cut, not the cupboard's paper cup."""
    assert _items("bring me a pen, I've got a paper cut") == ["pen"]


def test_a_name_said_exactly_is_unchanged() -> None:
    assert _items("bring me some sticky tape and a paper cup") == ["sticky_tape", "paper_cup"]


def test_an_everyday_word_is_no_slip_in_a_name() -> None:
    """ "my order for ..." is no "order form" typed with a slip: the "for" went to the name (and
    to a "form" of another thing), so in blind round 180 "sign my purchase order for the new
    rollers" asked what to do with the rollers."""
    raw = _raw_print_shop()
    raw["item_types"].append({"id": "order", "name": "order form", "kind": "personal"})
    office = ob.parsed(lambda: raw)()
    lex = InstructionParser(office).lex
    for text in ("bring my order for the new pen", "bring me my order for Rui"):
        said = [m.text.lower() for m in lex.read(text).mentions if m.kind == "item"]
        assert not any("for" in name.split() for name in said), said
    # must not change: a slip in a word that is no everyday word
    assert [m.ids for m in lex.read("bring my ordr form").mentions if m.kind == "item"] == [
        ("order",)
    ]
