"""The one a thing is taken from is not whom a receiving pronoun means, and hands it over:
"Ms Okafor needs her tape back, can you take it from Pat to her" is Pat's tape (the one Pat
has) for Ms Okafor, also where "from" is said in the clause before ("get it from June and
bring it to her"). "back to her" may be the one it came from, and is left as it was."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_HARBOUR = frame_reader(harbour_office, "will")
_DEFAULT = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "item", "giver", "who"),
    [
        ("Ms Okafor needs her tape back, can you take it from Pat to her", "tape", "pat", "may"),
        ("Ms Okafor needs her tape back. Can you take it from Pat to her?", "tape", "pat", "may"),
        ("Grace needs her ruler back, can you take it from Ken to her", "ruler", "ken", "grace"),
        (
            "Mr Lindqvist wants his ruler back, could you bring it from Joy to him",
            "ruler",
            "joy",
            "mark",
        ),
        (
            "Dr Huang wants her highlighter back - could you get it from June and bring it to her",
            "highlighter",
            "june",
            "grace",
        ),
        (
            "Prof. Sato needs her calculator back, grab it from Hope and take it to her",
            "calculator",
            "hope",
            "dawn",
        ),
    ],
)
def test_harbour_the_source_is_not_the_pronouns_person(
    text: str, item: str, giver: str, who: str
) -> None:
    frame = _HARBOUR(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", item, giver, who)], frame


@pytest.mark.parametrize(
    ("text", "item", "giver", "who"),
    [
        (
            "Mrs Wang needs her stapler back, could you take it from Gao Min to her",
            "stapler",
            "gao",
            "wang",
        ),
        (
            "Dr Zhang wants his stapler back, can you get it from Hu to him",
            "stapler",
            "hu",
            "zhang",
        ),
    ],
)
def test_default_office_the_source_is_not_the_pronouns_person(
    text: str, item: str, giver: str, who: str
) -> None:
    frame = _DEFAULT(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", item, giver, who)], frame


@pytest.mark.parametrize(
    "text",
    [
        "borrow Pat's tape and take it back to her",  # back to Pat: not made anyone else
        "get the ruler from Ken and take it back to him",
    ],
)
def test_must_not_change_back_to_the_one_it_came_from(text: str) -> None:
    frame = _HARBOUR(text)
    assert not frame.tasks and frame.question, frame


def test_must_not_change_from_and_to_named() -> None:
    frame = _HARBOUR("take the tape from Pat to May")
    got = [(t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("tape", "pat", "may")], frame


async def test_end_to_end_pats_tape_reaches_ms_okafor() -> None:
    text = "Ms Okafor needs her tape back, can you take it from Pat to her"
    run = await run_instruction(harbour_office(), "will", text)
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    assert run.sim.world.holder["tape:pat"] == "may", trace.summary
    assert not any(r.refused for r in trace.actions()), trace.summary
