"""A recipient given as a colleague's occasion ("bring some tape down to the post desk for
Grace's meeting", "take a ruler to the lounge for Mark's workshop"): the colleague whose
occasion it is receives the thing, unless the clause names someone else to receive it; the
room is where the occasion is, so whom there to hand it to is not asked, and the consent
guard lets the code go to them. A possessive of someone not of the office ("for the client's
meeting"), a benefit ("for Mark's sake") and an occasion with
no room the thing is taken to ("I need a ruler for Grace's workshop": why) stay as they were
(a plain "for Mark" with a room: test_room_for_a_colleague.py)."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_HARBOUR = frame_reader(harbour_office, "will")
_DEFAULT = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "item", "owner", "who"),
    [
        ("bring some tape down to the post desk for Grace's meeting", "tape", None, "grace"),
        ("take a ruler to the lounge for Mark's workshop", "ruler", None, "mark"),
        ("take a calculator to the kitchen for Ken's talk", "calculator", None, "ken"),
        (
            "bring Mark's ruler to the copy room for Grace's presentation",
            "ruler",
            "mark",
            "grace",
        ),
    ],
)
def test_harbour_the_occasions_colleague_receives(
    text: str, item: str, owner: str | None, who: str
) -> None:
    frame = _HARBOUR(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", item, owner, who)], frame


@pytest.mark.parametrize(
    ("text", "item", "who"),
    [
        ("take a stapler to the meeting room for Zhang's meeting", "stapler", "zhang"),
        ("bring some scissors down to the print room for Wang's workshop", "scissors", "wang"),
    ],
)
def test_default_office_the_occasions_colleague_receives(text: str, item: str, who: str) -> None:
    frame = _DEFAULT(text)
    got = [(t.kind, t.item, t.recipient) for t in frame.tasks]
    assert got == [("transfer", item, who)], frame


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("take a ruler to Joy for Mark's workshop", "joy"),  # Joy named to receive it
        ("bring me a ruler for Mark's workshop", "will"),
    ],
)
def test_must_not_change_a_named_recipient_wins(text: str, who: str) -> None:
    frame = _HARBOUR(text)
    assert [t.recipient for t in frame.tasks] == [who], frame


@pytest.mark.parametrize(
    "text",
    [
        "bring a highlighter down to the lounge for the client's meeting",  # nobody of ours
        "take a ruler to the post desk for Mark's sake",
        "take Grace's ruler to the lounge",
    ],
)
def test_must_not_change_other_possessives_are_still_asked(text: str) -> None:
    frame = _HARBOUR(text)
    assert not frame.tasks and frame.question, frame


def test_the_guard_reads_the_occasions_colleague_as_named() -> None:
    office = harbour_office()
    said = "bring some tape down to the post desk for Grace's meeting"
    assert "grace" in named_recipients(office, memory("will", said))
    assert "grace" not in named_recipients(office, memory("will", "take Grace's ruler to Joy"))


async def test_end_to_end_grace_gets_the_tape_for_her_meeting() -> None:
    text = "bring some tape down to the post desk for Grace's meeting"
    run = await run_instruction(harbour_office(), "will", text)
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    held = [i for i, who in run.sim.world.holder.items() if i.startswith("tape:")]
    assert any(run.sim.world.holder[i] == "grace" for i in held), trace.summary
    assert not any(r.refused for r in trace.actions()), trace.summary


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("I need a ruler for Grace's workshop", "will"),  # why, not whom: no room
        ("print my file for Grace's meeting", "will"),
        ("make a tea for Mark's meeting", "will"),
    ],
)
def test_must_not_change_without_a_room_the_occasion_says_why(text: str, who: str) -> None:
    frame = _HARBOUR(text)
    assert [t.recipient for t in frame.tasks] == [who], frame
    said = named_recipients(harbour_office(), memory("will", text))
    assert not said - {"will"}, said
