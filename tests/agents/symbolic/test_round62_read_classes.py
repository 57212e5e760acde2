"""Classes of the rounds read after stop 62's final measure (a stained glass studio, a
geology core store, a bridal alterations room), by mechanism, on a small glass studio built
here and on the default office:

- a portion said after a need ("I need safety glasses. Can you find me a pair?") is that
  thing, asked once (it asked what "a pair" meant);
- a clause of time whose subject is the speaker and whose words name a machine ("before I go
  near the grinder") says when, never the machine's work on the thing asked for;
- a time said after a bare occasion ("for fieldwork tomorrow", "for class tomorrow") is the
  occasion's: the thing is wanted now, not put off;
- "for <doing> <thing>" ("tissue paper for packing a veil", "scissors for cutting the paper")
  is what the thing asked for is used on, as "to pack a veil" is: never a second thing."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, load_office, parse_office
from helpers import office_builder as ob


@functools.cache
def _studio() -> Office:
    people = (
        ob.person("mercy", "Mercy Agyeman", "safety_glasses", "glass_piece"),
        ob.person("bjorn", "Björn Lund", "safety_glasses", "glass_piece"),
        ob.person("ruth", "Ruth Baker", "safety_glasses", "glass_piece", "veil"),
    )
    raw = ob.office_file(
        "glass studio",
        people,
        rooms=[ob.room("grinding_bay", "Grinding bay", 4.0, 20.5)],
        item_types=[
            ob.item("safety_glasses", "safety glasses"),
            ob.item("glass_piece", "glass piece", "personal", synonyms=["piece"]),
            ob.item("veil", "veil", "personal"),
            ob.item("tissue", "tissue paper", synonyms=["tissue"]),
        ],
        operations=[ob.operation("grind", "grind", "smooth", input="glass_piece")],
        facilities=[
            ob.facility(
                "grinder",
                "glass grinder",
                at="grinding_bay",
                guards=["bjorn"],
                operations=["grind"],
                supplies=[{"type": "tissue", "count": 5}],
                synonyms=["grinder"],
            )
        ],
        home="grinding_bay",
    )
    return parse_office(raw, raw["name"])


@functools.cache
def _parser(office: str) -> InstructionParser:
    return InstructionParser(_studio() if office == "studio" else load_office())


def _tasks(office: str, text: str, requester: str) -> list[tuple[str, str | None, str | None]]:
    frame = _parser(office).parse(text, requester)
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("office", "text", "requester", "item"),
    [
        ("studio", "I need safety glasses. Can you find me a pair?", "mercy", "safety_glasses"),
        ("default", "I need scissors. Can you find me a pair?", "zhang", "scissors"),
    ],
)
def test_a_portion_after_a_need_is_that_thing_once(
    office: str, text: str, requester: str, item: str
) -> None:
    assert _tasks(office, text, requester) == [("transfer", item, requester)]


def test_a_portion_with_nothing_named_is_still_asked() -> None:
    frame = _parser("default").parse("bring me a pair", "zhang")
    assert frame.tasks == [] and frame.question is not None


@pytest.mark.parametrize(
    "text",
    [
        "I need safety glasses before I go near the grinder. Can you find me a pair?",
        "I need safety glasses before I use the grinder",
    ],
)
def test_the_speakers_time_clause_naming_a_machine_says_when(text: str) -> None:
    assert _tasks("studio", text, "mercy") == [("transfer", "safety_glasses", "mercy")]


def test_the_machines_work_asked_beside_a_time_clause_is_still_done() -> None:
    """Near-miss: "grind my glass piece before I go home" is the grinder's work."""
    frame = _parser("studio").parse("could you grind my glass piece before I go home", "mercy")
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("heat", "glass_piece", "mercy")]


@pytest.mark.parametrize(
    "text", ["I need a data cable for class tomorrow", "I need a book for training on Friday"]
)
def test_a_time_after_a_bare_occasion_wants_the_thing_now(text: str) -> None:
    assert len(_tasks("default", text, "zhang")) == 1


@pytest.mark.parametrize("text", ["I need a data cable tomorrow", "I might need a book later"])
def test_a_need_for_later_is_still_put_off(text: str) -> None:
    """Near-miss: a time said of the need itself puts it off, as before."""
    frame = _parser("default").parse(text, "zhang")
    assert frame.tasks == [] and frame.decline is not None


@pytest.mark.parametrize(
    ("office", "text", "requester", "item"),
    [
        ("studio", "Could I get some tissue paper for packing a veil?", "ruth", "tissue"),
        ("studio", "could I get tissue for wrapping my glass piece", "ruth", "tissue"),
        ("default", "bring me scissors for cutting the paper", "zhang", "scissors"),
        ("default", "bring me some wipes for cleaning my cup", "zhang", "wipes"),
    ],
)
def test_what_a_thing_is_used_on_is_no_second_thing(
    office: str, text: str, requester: str, item: str
) -> None:
    assert _tasks(office, text, requester) == [("transfer", item, requester)]
