"""Idioms that equal a colleague's first name are words, and a thing named in the reason with
a demonstrative is what the speaker already holds (blind round 16's class 5; the round's
office and sentences were never read). "to be frank i can't see a thing on these printouts.
bring me an eyeglass?" asks for a magnifying glass only: "to be frank" is the speaker's
stance (like "frankly"), never Frank Osei, and "these printouts" are in the speaker's hand,
never printed again. "mark my words", "will do", "sunny side up" stay words too."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import Inquire
from assistantx.core.task_schema import TaskFrame
from helpers.gazette import newsroom
from helpers.reading import answered_reader

_frame = answered_reader(newsroom, "ines")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


_GLASS = [("transfer", "magnifying_glass", None, "ines")]


@pytest.mark.parametrize(
    "text",
    [
        "to be frank i can't see a thing on these printouts. bring me an eyeglass?",
        "to be frank i can't see a thing on these negatives. bring me an eyeglass?",
        "to be blunt, i can't see a thing on these printouts. bring me a magnifying glass?",
        "frankly i can't see a thing on these printouts. bring me an eyeglass?",
        "to be honest i can't see a thing on these hard copies. bring me an eyeglass?",
        "can't read these printouts, bring me an eyeglass",
        "can't see a thing on these negatives. bring me an eyeglass?",
        "mark my words, i can't see a thing on these negatives. bring me a magnifying glass?",
        "will do. i can't see a thing on these printouts, bring me an eyeglass?",
        "sunny side up, these negatives look fine. bring me an eyeglass?",
        "to be frank i need an eyeglass",
    ],
)
def test_only_the_thing_asked_for_is_brought(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None
    assert _tasks(frame) == _GLASS


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("bring Frank an eyeglass", [("transfer", "magnifying_glass", None, "frank")]),
        ("ask Frank for his cutting mat", [("transfer", "cutting_mat", "frank", "ines")]),
        ("give Will an eyeglass", [("transfer", "magnifying_glass", None, "will")]),
        ("can't you bring me an eyeglass?", _GLASS),
        ("can't print my draft, can you print it for me", [("print", "file", "ines", "ines")]),
    ],
)
def test_the_people_and_requests_stay_as_they_were(
    text: str, expected: list[tuple[str, str | None, str | None, str]]
) -> None:
    assert _tasks(_frame(text)) == expected


@pytest.mark.parametrize(
    "text",
    ["to be frank, these prints are blurry", "will do, thanks", "mark my words"],
)
def test_idioms_alone_move_nothing(text: str) -> None:
    assert _frame(text).tasks == []


async def test_a_run_asks_no_frank_and_prints_nothing() -> None:
    run = await run_instruction(
        newsroom(),
        "ines",
        "to be frank i can't see a thing on these printouts. bring me an eyeglass?",
    )
    acted = [r.action for r in run.stm.trace.actions() if not r.refused]
    assert "frank" not in {a.contact for a in acted if isinstance(a, Inquire)}
    assert not run.sim.world.printed and not run.sim.world.made
