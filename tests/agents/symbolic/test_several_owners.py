""" "the X" taken to a colleague, where the requester has none and several colleagues besides
the recipient each have one, asks whose it is ("could you take the tray over to ..." acted on a
guessed owner: blind round 28's class); the answer is read as the owner. A requester's own, a
single owner, a supply, "a X" or an owner said are read as before."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import Move
from helpers.reading import answered_reader, frame_reader
from helpers.tyre_bay import tyre_bay

Row = tuple[str, str | None, str | None, str | None]

_frame = frame_reader(tyre_bay, "marlo")  # Marlo has no tray and no ruler
_answered = answered_reader(tyre_bay, "marlo")


def _tasks(text: str, who: str = "marlo") -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in _frame(text, who).tasks]


@pytest.mark.parametrize(
    ("text", "name"),
    [
        ("could you take the tray over to Amber", "tray"),
        ("take the ruler to Amber", "ruler"),
        ("pop the tray over to amber pls", "tray"),
        ("could you carry the ruler over to Amber", "ruler"),
    ],
)
def test_the_thing_several_colleagues_have_is_asked_about(text: str, name: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is None, frame
    assert frame.question is not None and f"whose {name} do you mean" in frame.question


@pytest.mark.parametrize(
    ("answer", "owner"),
    [("Bruno Keel's.", "bruno"), ("Tove's tray", "tove"), ("Anyone's, any will do.", None)],
)
def test_the_answer_names_the_owner(answer: str, owner: str | None) -> None:
    frame = _answered("could you take the tray over to Amber", [answer])
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "tray", owner, "amber")
    ], frame


def test_no_answer_leaves_it_asked() -> None:
    frame = _answered("could you take the tray over to Amber", ["Sorry, I don't know."])
    assert frame.tasks == [] and frame.question is not None, frame


@pytest.mark.parametrize(
    ("text", "who", "expected"),
    [
        ("could you take the tray over to Amber", "ines", ("transfer", "tray", "ines", "amber")),
        ("take the ruler to Bruno", "marlo", ("transfer", "ruler", None, "bruno")),
        ("take the clipboard to Amber", "ines", ("transfer", "clipboard", None, "amber")),
        ("bring Amber a tray", "marlo", ("transfer", "tray", None, "amber")),
        ("take Bruno's tray to Amber", "marlo", ("transfer", "tray", "bruno", "amber")),
        ("take the tray from Bruno to Amber", "marlo", ("transfer", "tray", "bruno", "amber")),
        ("take the box of staples to Amber", "marlo", ("transfer", "staples", None, "amber")),
        ("bring me the tray", "marlo", ("transfer", "tray", None, "marlo")),
        ("can you bring Amber the tray", "marlo", ("transfer", "tray", None, "amber")),
        ("bring the ruler to Amber", "marlo", ("transfer", "ruler", None, "amber")),
    ],
)
def test_other_readings_are_unchanged(text: str, who: str, expected: Row) -> None:
    assert _tasks(text, who) == [expected]


@pytest.mark.parametrize(
    "text", ["did you take the tray to Amber?", "don't take the tray to Amber"]
)
def test_a_question_or_negation_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []


async def test_end_to_end_no_tray_moves_on_a_guessed_owner() -> None:
    run = await run_instruction(tyre_bay(), "marlo", "could you take the tray over to Amber")
    trace = run.stm.trace
    contacts = {getattr(r.action, "contact", None) for r in trace.actions()}
    assert not contacts & {"ines", "bruno", "tove"}, trace.summary
    assert not any(isinstance(r.action, Move) for r in trace.actions()), trace.summary
