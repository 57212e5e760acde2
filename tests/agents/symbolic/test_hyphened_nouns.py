"""A verb and its particle hyphened after a determiner and before a noun name a thing or an
event ("a pen for the warm-up drill"), never the work asked (``reading.hyphened_nouns``): the
default office heats things, and read "warm" as heating a pen, declined. A compound the office
names, or one with no noun after it ("take the print-out to Mao": the printout made), keeps
its reading."""

from __future__ import annotations

import pytest
from _offices import tasks_of

from assistantx.agents.symbolic.reading.hyphened_nouns import hyphened_nouns


@pytest.mark.parametrize(
    "text",
    [
        "Could you bring me a pen for the warm-up drill?",
        "can I get a stapler for the warm-up session pls",
        "bring me a pen for the sign-off meeting",
    ],
)
def test_the_thing_is_brought_for_the_event(text: str) -> None:
    tasks = tasks_of("default", text, "lee")
    assert [(k, i, r) for k, i, _, r in tasks] in (
        [("transfer", "pen", "lee")],
        [("transfer", "stapler", "lee")],
    )


def test_the_print_out_after_printing_is_still_the_printout() -> None:
    tasks = tasks_of("default", "print my file and take the print-out to Mao", "lee")
    assert tasks == [("print", "file", "lee", "mao")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("a pen for the warm-up drill", "a pen for the warmup drill"),
        ("take the print-out to Mao", "take the print-out to Mao"),  # no noun after it
        ("the print-out paper", "the print-out paper"),  # the office's word after it
    ],
)
def test_the_rewrite(text: str, expected: str) -> None:
    assert hyphened_nouns(text, frozenset({"paper"})) == expected


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("drop-in visitor needs a pen, can you bring me one", "pen"),
        ("Walk-in forgot theirs, can you fetch me a stapler?", "stapler"),
        ("Stand-by team needs scissors, bring me some", "scissors"),
    ],
)
def test_a_compound_opening_a_clause_is_its_subject(text: str, item: str) -> None:
    """ "Walk-in forgot theirs": a noun, the clause's subject, never the verb "walk" asked
    (declined "I can't walk", blind round 256) nor "in visitor" a recipient."""
    tasks = tasks_of("default", text, "lee")
    assert [(k, i, r) for k, i, _, r in tasks] == [("transfer", item, "lee")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("Walk-in forgot theirs", "Walkin forgot theirs"),
        ("thanks. drop-in visitor needs one", "thanks. dropin visitor needs one"),
        ("pick-up my parcel", "pick-up my parcel"),  # the verb, its object after it
        ("check-in till is down", "check-in till is down"),  # the office's own word
    ],
)
def test_the_opening_rewrite(text: str, expected: str) -> None:
    assert hyphened_nouns(text, frozenset({"checkin"})) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("walk it over to Wang", None),  # the verb: declined as before
        ("drop in my stapler to Wang", [("transfer", "stapler", "lee", "wang")]),
    ],
)
def test_the_verb_unhyphened_keeps_its_reading(
    text: str, expected: list[tuple[str, str, str, str]] | None
) -> None:
    tasks = tasks_of("default", text, "lee")
    if expected is None:
        assert tasks == []
    else:
        assert tasks == expected
