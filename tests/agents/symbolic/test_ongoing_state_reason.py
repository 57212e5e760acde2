"""A reason told after a request about another thing of the office, "my X's <verb>-ing ...":
"need rosin, my bow's squeaking like mad". After the name of one of the office's things, the
"'s" before a verb's "-ing" is "is" also when words of how or when follow ("like mad", "when I
play"), so the clause is why the request is made, never a second thing asked for ("Who should
get your bow?"); a noun after the "-ing" is still the thing's part (``screen.contracted_is``)."""

from __future__ import annotations

import functools

import pytest
from _offices import parser, tasks_of

from assistantx.agents.symbolic import InstructionParser
from assistantx.agents.symbolic.reading.screen.contracted_is import contracted_is
from helpers.music_school import music_school


@functools.cache
def _music() -> InstructionParser:
    return InstructionParser(music_school())


def _tasks(text: str, requester: str) -> list[tuple[str, str | None, str | None, str]]:
    frame = _music().parse(text, requester)
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("need rosin, my bow's squeaking like mad", "rosin"),
        ("need rosin, my bow's squeaking when I play", "rosin"),
        ("need some glue, my folder's falling apart", "glue"),
        ("could I get some glue? my folder's coming apart at the spine", "glue"),
    ],
)
def test_the_reason_asks_for_nothing_more_music_school(text: str, item: str) -> None:
    assert _tasks(text, "tom") == [("transfer", item, None, "tom")]


def test_the_reason_asks_for_nothing_more_default() -> None:
    assert tasks_of("default", "need a pen, my stapler's sticking like glue", "zhang") == [
        ("transfer", "pen", None, "zhang")
    ]
    assert tasks_of("default", "need a pen, mine's run dry", "zhang") == [
        ("transfer", "pen", None, "zhang")
    ]


def test_the_reason_asks_for_nothing_more_harbour() -> None:
    frame = parser("harbour").parse("need a notepad, my calculator's beeping like crazy", "will")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("notepad", "will")]
    assert frame.question is None


def test_two_things_named_are_still_two() -> None:
    # must not change: "need rosin and my bow" names the bow as wanted too, so it is asked
    frame = _music().parse("need rosin and my bow", "tom")
    assert frame.question is not None and "bow" in frame.question


def test_a_noun_after_the_ing_is_still_a_part() -> None:
    # must not change: "the printer's working copy" is no state of the printer
    said, _ = contracted_is("the bow's tuning peg is loose", frozenset({"bow", "peg"}))
    assert said == "the bow's tuning peg is loose"
