""" "one from <colleague>" names that colleague's thing, as "a ruler from Mark" does: "Mrs
Okafor needs a ruler, can you take one from Mark to her" takes Mark's ruler (asked of Mark)
to May, not anyone's. "one" with no colleague after it, or from two colleagues, or from a
place, names no owner."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic.reading.one_from import owned_as_one_from
from assistantx.core.task_schema import Task
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_HARBOUR = frame_reader(harbour_office, "grace")
_DEFAULT = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "item", "owner", "who"),
    [
        ("Mrs Okafor needs a ruler, can you take one from Mark to her", "ruler", "mark", "may"),
        ("May needs a calculator, please take one from Dawn to her", "calculator", "dawn", "may"),
        ("Will has run out of tape, could you bring him one from Jack", "tape", "jack", "will"),
    ],
)
def test_harbour_one_from_a_colleague_is_theirs(text: str, item: str, owner: str, who: str) -> None:
    frame = _HARBOUR(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", item, owner, who)], frame


def test_default_office_one_from_a_colleague_is_theirs() -> None:
    frame = _DEFAULT("Chen needs a stapler, can you take one from Wang to him")
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", "stapler", "wang", "chen")], frame


@pytest.mark.parametrize(
    ("text", "office", "who"),
    [
        ("May needs a ruler, take one to her", harbour_office, "may"),  # nobody's in particular
        ("I need a stapler, can you get one from the kitchen", default_office, "lee"),  # a place
    ],
)
def test_must_not_change_one_from_no_colleague_names_no_owner(
    text: str, office: object, who: str
) -> None:
    frame = (_HARBOUR if office is harbour_office else _DEFAULT)(text)
    assert [(t.owner, t.recipient) for t in frame.tasks] == [(None, who)], frame


def test_a_thing_going_to_the_one_it_is_from_keeps_no_owner() -> None:
    task = Task(kind="transfer", item="ruler", recipient="mark")
    assert owned_as_one_from(task, "mark").owner is None
    assert owned_as_one_from(task, "joy").owner == "joy"


async def test_end_to_end_mark_hands_over_his_ruler_for_may() -> None:
    text = "Mrs Okafor needs a ruler, can you take one from Mark to her"
    run = await run_instruction(harbour_office(), "grace", text)
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    assert run.sim.world.holder.get("ruler:mark") == "may", trace.summary
    asked = [a for a in trace.actions() if a.action.type == "inquire"]
    assert asked and "mark" in str(asked[0].action), trace.summary
