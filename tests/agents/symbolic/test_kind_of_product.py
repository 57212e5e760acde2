"""A kind of a made thing the office names by its plain name only ("a flat white" where the
coffee machine makes coffee, "a chai" where the urn makes tea) is asked about: "Shall I get a
coffee instead?", a yes getting the office's own, a no nothing. It was declined as a thing
nobody here has. Left from earlier stops' blind sets (the default office's "a flat white")."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import load_office
from helpers.hostel import hostel


@functools.cache
def _default() -> InstructionParser:
    return InstructionParser(load_office())


@functools.cache
def _hostel() -> InstructionParser:
    return InstructionParser(hostel())


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("could you get me a flat white", "a flat white"),
        ("id kill for a macchiato rn", "a macchiato"),
        ("2 flat whites for me and Wang please", "a flat white"),
        ("Flat White for Wang pls", "a flat white"),
    ],
)
def test_a_kind_of_the_offices_coffee_is_asked_about(text: str, kind: str) -> None:
    frame = _default().parse(text, "zhang")
    assert not frame.tasks and frame.decline is None
    assert frame.question is not None
    assert f"{kind} is not something this office makes" in frame.question
    assert "Shall I get a coffee instead?" in frame.question


@pytest.mark.parametrize(
    ("text", "answer", "made"),
    [
        ("could you get me a flat white", "yes please", [("coffee", "zhang")]),
        ("a flat white for Wang please", "yes", [("coffee", "wang")]),
        ("2 flat whites for me and Wang please", "yes", [("coffee", "zhang"), ("coffee", "wang")]),
        ("could you get me a flat white", "no thanks", []),
    ],
)
def test_the_answer_gets_the_offices_own_or_nothing(
    text: str, answer: str, made: list[tuple[str, str]]
) -> None:
    frame = _default().parse_with_answers(text, "zhang", [answer])
    assert [(t.item, t.recipient) for t in frame.tasks if t.kind == "produce"] == made
    assert frame.question is None


def test_a_kind_of_tea_where_the_urn_makes_tea() -> None:
    frame = _hostel().parse("could I get a chai please", "hamid")
    assert frame.question is not None and "Shall I get a tea instead?" in frame.question


@pytest.mark.parametrize(
    ("text", "item"),
    [
        # near-misses: the office's own names for its coffee are read as before
        ("grab me a latte pls", "coffee"),
        ("could you get me a coffee", "coffee"),
        ("a tea for me please", "tea"),
    ],
)
def test_a_name_the_office_gives_is_made_at_once(text: str, item: str) -> None:
    parser = _default() if item == "coffee" else _hostel()
    frame = parser.parse(text, "zhang" if item == "coffee" else "hamid")
    assert [t.item for t in frame.tasks] == [item] and frame.question is None


def test_someones_own_drink_is_no_kind_to_make() -> None:
    """Near-miss: "Wang's flat white" is Wang's, never offered as a coffee made here."""
    frame = _default().parse("bring me Wang's flat white", "zhang")
    assert frame.tasks == []
    assert frame.question is None or "instead" not in frame.question


def test_an_office_that_makes_no_coffee_still_declines() -> None:
    """Near-miss: a hostel whose kitchen makes tea and hot chocolate has no coffee to offer."""
    frame = _hostel().parse("could you get me a flat white", "hamid")
    assert frame.tasks == [] and frame.question is None
    assert frame.decline is not None and "no flat white" in frame.decline


@pytest.mark.parametrize(
    "text",
    [
        # near-misses: a coffee where only tea is made is no kind of tea; a preference
        # beside the office's own name asks nothing
        "could you make me a coffee",
        "can you get me a sandwich from the kitchen",
    ],
)
def test_a_thing_of_the_same_sort_is_not_offered(text: str) -> None:
    frame = _hostel().parse(text, "hamid")
    assert "instead" not in (frame.question or "")


def test_a_preference_beside_the_offices_own_name_gets_it() -> None:
    frame = _default().parse("cud u grab me a coffee, flat white if poss", "lin")
    assert [(t.kind, t.item) for t in frame.tasks] == [("produce", "coffee")]


def test_a_kind_asked_of_the_machine_that_makes_the_thing_gets_it() -> None:
    """Near-miss: "from the coffee machine" says it is the machine's coffee that is wanted."""
    frame = _default().parse("grab me a flat white from the coffee machine", "lin")
    assert [(t.kind, t.item) for t in frame.tasks] == [("produce", "coffee")]
