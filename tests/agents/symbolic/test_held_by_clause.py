"""A relative clause names the owner or holder (fix129d, class 2): "I need the draft Zoltán
has, can you get it to me?" passed the requester's own file to herself, and "bring me the
stapler Zhang's got" lent a stapler of someone not named. "the X <Name> has / has got / 's got
/ is holding", "the X that <Name> has" and "the X, <Name> has it" name that colleague's X
(reading/held_by_clause.py), asked for as any owned thing. "the file I have" (the requester's
own), "the file Wang has signed" (a perfect) and "the file the team has" are left as said."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.held_by_clause import held_by_clauses
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader, parser_for

_default = frame_reader(default_office, "lin")
_harbour = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("I need the file Wang has, can you get it to me?", "file", "wang"),
        ("bring me the stapler Zhang's got", "stapler", "zhang"),
        ("bring me the stapler that Wang has", "stapler", "wang"),
        ("bring me the stapler Wang is holding", "stapler", "wang"),
        ("could you get me the seal Wang Fang has got please", "seal", "wang"),
        ("I need the file, Wang has it", "file", "wang"),
        ("I need the book Lee has, bring it over", "book", "lee"),
    ],
)
def test_the_colleague_of_the_clause_owns_it(text: str, item: str, owner: str) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [(item, owner, "lin")], frame


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("can you get me the charger Ray has got", "charger", "ray"),
        ("I need the ruler that Ken has, bring it over", "ruler", "ken"),
        ("bring me the highlighter June's got", "highlighter", "june"),
    ],
)
def test_the_same_in_another_office(text: str, item: str, owner: str) -> None:
    frame = _harbour(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [(item, owner, "may")], frame


def test_the_thing_the_requester_has_is_still_their_own() -> None:
    frame = _default("I need the file I have")
    assert frame.question == "Who should I pass your file on to?", frame


@pytest.mark.parametrize(
    "text",
    [
        "bring me the file Wang has signed",  # "has signed": a perfect, no clause of having
        "bring me the file the team has",  # no colleague
        "the file I have",  # the requester's own
        "give the stapler to Wang, he has none",
        "the kettle died, Wang has it in hand",  # a fault and who deals with it
        "the printer jammed - Zhang has it under control",
    ],
)
def test_no_clause_of_a_colleagues_having_is_left_as_said(text: str) -> None:
    terms = parser_for(default_office).screen.terms
    assert held_by_clauses(text, terms.is_person_word) == text


def test_a_two_word_name_and_a_described_thing() -> None:
    terms = parser_for(default_office).screen.terms
    said = held_by_clauses("bring me the budget file Wang Fang has got", terms.is_person_word)
    assert said == "bring me Wang Fang's budget file"
