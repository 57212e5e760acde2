"""A one-word name means whom the office file says it is used for: a title with a surname
("Dr Ellis") the one addressed so, a role with its qualifier ("the practice manager") the one
with that whole role, never everyone who shares the word or the role noun (blind round 4,
classes A1-A4; own office and sentences). A bare alias ("Ellis") that is Ellis Grant's given name
and Dawn Ellis's family name is his: colleagues speak of her as "Dr Ellis", of him as "Ellis"
(``given_name_meant``: outside testers of English-named offices expected the given name every
time); a family name the office writes after a rank is still asked about (round 81's
"Inspector Morgan", ``family_of_another``); an item only one of them owns still says whose it
is."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers.clinic import raw_clinic


@functools.cache
def clinic_with_declared_names() -> InstructionParser:
    """The clinic, with Ellis Grant (called "Ellis") beside Dawn Ellis (called "Dr. Ellis"),
    and two managers told apart by their role's qualifier."""
    raw = raw_clinic()
    aliases = {
        "dawn": ["Dr. Ellis"],
        "rich": ["the practice manager"],
        "hal": ["the office manager"],
    }
    for p in raw["people"]:
        p["aliases"] = aliases.get(p["id"], [])
    raw["people"].append(
        {
            "id": "grant",
            "name": "Ellis Grant",
            "aliases": ["Ellis"],
            "location": "desk_7",
            "handle": "@grant",
            "owns": [{"type": "clipboard"}, {"type": "document"}],
        }
    )
    return InstructionParser(parse_office(raw, "clinic with declared names"))


def _parties(text: str) -> list[tuple[str, str | None, str, str | None]]:
    frame = clinic_with_declared_names().parse(text, "ines")
    assert frame.question is None, frame.question
    return [(t.kind, t.owner, t.recipient, t.actor) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("take my form to Dr Ellis", "dawn"),  # the title and surname
        ("take my form to Dr. Ellis please", "dawn"),
    ],
)
def test_a_name_goes_to_whom_the_office_calls_so(text: str, who: str) -> None:
    assert [t[2] for t in _parties(text)] == [who]


def test_a_bare_alias_that_is_his_given_name_and_her_family_name_is_his() -> None:
    assert [t[2] for t in _parties("take my form to Ellis")] == ["grant"]
    assert [t[2] for t in _parties("take my form to Dr Ellis")] == ["dawn"]
    assert [t[2] for t in _parties("take my form to Ellis Grant")] == ["grant"]


def test_a_possessive_bare_alias_is_its_person() -> None:
    assert [t[1] for t in _parties("bring me Ellis's clipboard")] == ["grant"]


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("ask the practice manager to sign my form", "rich"),
        ("could the office manager sign my form?", "hal"),
    ],
)
def test_a_role_with_its_qualifier_is_the_one_with_that_role(text: str, who: str) -> None:
    assert [t[3] for t in _parties(text)] == [who]


def test_the_possessive_of_a_qualified_role_owns_the_item() -> None:
    assert [t[1] for t in _parties("bring me the office manager's thermometer")] == ["hal"]


def test_the_role_noun_alone_still_asks_which() -> None:
    frame = clinic_with_declared_names().parse("ask the manager to sign my form", "ines")
    assert frame.tasks == [] and frame.question is not None
    assert "Rich Adeyemi" in frame.question and "Hal Brooks" in frame.question
