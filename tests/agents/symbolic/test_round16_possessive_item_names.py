"""Blind round 16, class 3: an item's own name written like a possessive.

On a small newsroom no sentence was written for (``helpers.newsroom``; the round's office
and sentences were never read), the stationery cupboard keeps "reporter's notebook"s for
anyone. The office's own name with "'s" inside is the item, not "reporter" looked up as a
colleague; a polite "would somebody be able to ...?" with a trailing "Thanks!" is still the
request; a person's name before "'s" is still a person, and thanks alone moves nothing."""

from __future__ import annotations

import functools

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, parse_office
from helpers.newsroom import newsroom, raw_newsroom


def _named_by_id_too() -> Office:
    """The same office, its notebook's id spelled from its name ("reporters_notebook"), so
    no one-word id matches "notebook" alone."""
    raw = raw_newsroom()
    for t in raw["item_types"]:
        if t["id"] == "notebook":
            t["id"] = "reporters_notebook"
    for f in raw["facilities"]:
        f["supplies"] = [
            {**s, "type": "reporters_notebook"} if s["type"] == "notebook" else s
            for s in f.get("supplies", [])
        ]
    return parse_office(raw, "newsroom-notebook-id")


_OFFICES = {"newsroom": newsroom(), "by_id": _named_by_id_too()}


@functools.cache
def _parser(name: str) -> InstructionParser:
    return InstructionParser(_OFFICES[name])


@pytest.mark.parametrize(
    ("office", "notebook"), [("newsroom", "notebook"), ("by_id", "reporters_notebook")]
)
@pytest.mark.parametrize(
    "text",
    [
        "Would somebody be able to bring me a reporter's notebook from the cupboard? Thanks!",
        "Would somebody be able to bring me a reporter's notebook from the cupboard?",
        "Would anyone be able to grab me a reporter’s notebook? Cheers!",
        "could someone fetch me two reporter's notebooks, thanks",
        "bring me a reporter's notebook please",
        "Is anybody able to bring me a reporter's notebook? Thank you so much!",
    ],
)
def test_the_office_name_with_a_possessive_is_the_item(
    office: str, notebook: str, text: str
) -> None:
    frame = _parser(office).parse(text, "ines")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", notebook, "ines")]


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("bring me Tomas's lanyard", "tomas"),
        ("Would somebody bring me Marta's lanyard? Thanks!", "marta"),
    ],
)
def test_a_colleagues_name_before_s_is_still_theirs(text: str, owner: str) -> None:
    frame = _parser("newsroom").parse(text, "ines")
    assert [(t.item, t.owner) for t in frame.tasks] == [("lanyard", owner)]


def test_an_unknown_name_before_s_is_still_asked() -> None:
    frame = _parser("newsroom").parse("bring me Smith's lanyard", "ines")
    assert frame.tasks == [] and "Smith" in (frame.question or "")


@pytest.mark.parametrize(
    "text",
    [
        "Thanks for the reporter's notebook!",
        "Would somebody be able to bring me a reporter's notebook? No wait, I found one. Thanks!",
        "does the cupboard have a reporter's notebook?",
        "I don't need a reporter's notebook, thanks",
    ],
)
def test_thanks_questions_and_withdrawals_move_nothing(text: str) -> None:
    assert _parser("by_id").parse(text, "ines").tasks == []


async def test_the_notebook_comes_from_the_cupboard() -> None:
    run = await run_instruction(
        newsroom(),
        "ines",
        "Would somebody be able to bring me a reporter's notebook from the cupboard? Thanks!",
    )
    assert run.stm.trace.outcome == "done"
    assert run.sim.world.holder["notebook:cupboard"] == "ines"


@pytest.mark.parametrize(
    "text", ["bring me a visitor's lanyard", "could you get me a visitor's pen"]
)
def test_a_kind_of_person_before_s_in_lower_case_is_no_name(text: str) -> None:
    """ "a visitor's lanyard": an ordinary noun after "a", not someone to look up."""
    frame = _parser("newsroom").parse(text, "ines")
    assert "anyone called" not in (frame.question or "")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("transfer", "ines")]
