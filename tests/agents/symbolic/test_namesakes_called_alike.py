"""Two colleagues called by the same name ("Noor" for Noor Haddad and Noor Salem): the item
said to be the name's ("Noor's controller") does not say which, even where only one of them
is known to keep one. The assistant's record is of what it knows, not of all anyone owns, so
it asks which one is meant; the answer settles it (``reading.called_by``). Where only one is
called so and the other merely has the word in their full name ("Yang's book": Yang Lei, not
Liu Yang), the record still says whom, as before."""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

import pytest
from _offices import parser as office_parser

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers import office_builder as ob
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.yaml_files import raw_yaml


def _raw_games_room() -> dict[str, Any]:
    people = (
        ob.person("ines", "Ines Ford", "pen"),
        ob.person("haddad", "Noor Haddad", "controller"),
        ob.person("salem", "Noor Salem", "pen"),
        ob.person("otto", "Otto Lind", "pen"),
    )
    return ob.office_file(
        "games room",
        people,
        rooms=[ob.room("store", "Store", 20.0, 20.0)],
        item_types=[ob.item("pen", "pen"), ob.item("controller", "controller")],
        operations=[],
        facilities=[],
        home="store",
    )


_games_room = ob.parsed(_raw_games_room)


@functools.cache
def _games_parser() -> InstructionParser:
    return InstructionParser(_games_room())


def _with_person(file: Any, person: dict[str, Any], name: str) -> InstructionParser:
    raw: dict[str, Any] = raw_yaml(file)
    raw["people"].append(person)
    return InstructionParser(parse_office(raw, name))


@functools.cache
def _harbour_with_two_graces() -> InstructionParser:
    # Grace Obi keeps no highlighter the assistant knows of; Grace Huang does
    grace = {"id": "obi", "name": "Grace Obi", "aliases": ["Grace"], "location": "desk_16"}
    return _with_person(HARBOUR_FILE, grace | {"handle": "@obi", "owns": []}, "two Graces")


@functools.cache
def _default_with_two_fangs() -> InstructionParser:
    # Fang Ito is called Fang, as Wang Fang is by the alias the office declares; only Wang
    # Fang keeps a seal on record
    fang = {"id": "ito", "name": "Fang Ito", "location": "desk_16", "handle": "@ito"}
    return _with_person(DEFAULT_FILE, fang | {"owns": [{"type": "pen"}]}, "two Fangs")


@pytest.mark.parametrize(
    ("parser", "text", "requester", "both", "answer", "owner"),
    [
        (_games_parser, "bring me Noor's controller", "ines", ("Noor Haddad", "Noor Salem"),
         "Noor Haddad", "haddad"),
        (_games_parser, "could you grab Noor's pen for me", "otto", ("Noor Haddad", "Noor Salem"),
         "Noor Salem", "salem"),
        (_harbour_with_two_graces, "can I borrow Grace's highlighter?", "may",
         ("Grace Huang", "Grace Obi"), "Grace Huang", "grace"),
        (_default_with_two_fangs, "please bring me Fang's seal", "mao", ("Wang Fang", "Fang Ito"),
         "Wang Fang", "wang"),
    ],
)  # fmt: skip
def test_two_called_so_are_asked_about_and_the_answer_settles_it(
    parser: Callable[[], InstructionParser],
    text: str,
    requester: str,
    both: tuple[str, str],
    answer: str,
    owner: str,
) -> None:
    p = parser()
    frame = p.parse(text, requester)
    assert frame.tasks == [] and frame.question is not None, frame
    assert all(name in frame.question for name in both), frame.question
    settled = p.parse_with_answers(text, requester, [answer])
    assert [(t.kind, t.owner, t.recipient) for t in settled.tasks] == [
        ("transfer", owner, requester)
    ], settled


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("bring me Noor Haddad's controller", "haddad"),  # the full name says which
        ("bring me Otto's pen", "otto"),  # one Otto
    ],
)
def test_a_name_only_one_is_called_is_taken(text: str, owner: str) -> None:
    frame = _games_parser().parse(text, "ines")
    assert [(t.owner, t.recipient) for t in frame.tasks] == [(owner, "ines")], frame


def test_called_so_beside_a_later_name_word_is_still_settled_by_the_record() -> None:
    """Must not change: "Yang" is how Yang Lei is called, and Liu Yang only has the word
    as his given name; only Yang Lei keeps a book, so "Yang's book" is hers, unasked."""
    frame = office_parser("default").parse("bring me Yang's book", "lee")
    assert [(t.owner, t.recipient) for t in frame.tasks] == [("yang", "lee")], frame
