"""A thing taken to a room "for" a colleague ("take a ruler to the lounge for Mark", "drop my
calculator at the kitchen for Rose"): with no one else named to receive it, that colleague
receives it, met as usual; the room is where it goes for them, so neither "I can't help with
the lounge" nor "who there should get it?" is asked. A room alone, or "for Mark's sake"
(a benefit, nobody's), still asks."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_HARBOUR = frame_reader(harbour_office, "grace")
_DEFAULT = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "item", "owner", "who"),
    [
        ("take a ruler to the lounge for Mark", "ruler", None, "mark"),
        ("drop my highlighter at the kitchen for Rose", "highlighter", "grace", "rose"),
        ("bring some tape to the post desk for Will", "tape", None, "will"),
        ("take a calculator into the lounge for Ken", "calculator", None, "ken"),
    ],
)
def test_harbour_the_colleague_the_thing_is_for_receives(
    text: str, item: str, owner: str | None, who: str
) -> None:
    frame = _HARBOUR(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", item, owner, who)], frame


@pytest.mark.parametrize(
    ("text", "item", "owner", "who"),
    [
        ("take a stapler to the meeting room for Zhang", "stapler", None, "zhang"),
        ("drop my book at the kitchen for Chen", "book", "lee", "chen"),
    ],
)
def test_default_office_the_colleague_the_thing_is_for_receives(
    text: str, item: str, owner: str | None, who: str
) -> None:
    frame = _DEFAULT(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", item, owner, who)], frame


@pytest.mark.parametrize(
    "text",
    [
        "take a ruler to the lounge",  # nobody it is for: the room's service is asked about
        "take a ruler to the lounge for Mark's sake",  # a benefit, nobody to hand it to
    ],
)
def test_must_not_change_a_room_with_nobody_it_is_for_is_asked(text: str) -> None:
    frame = _HARBOUR(text)
    assert not frame.tasks and frame.question, frame


def test_the_guard_reads_the_colleague_as_named() -> None:
    said = memory("grace", "take a ruler to the lounge for Mark")
    assert "mark" in named_recipients(harbour_office(), said)


async def test_end_to_end_mark_gets_a_ruler_taken_to_the_lounge_for_him() -> None:
    run = await run_instruction(harbour_office(), "grace", "take a ruler to the lounge for Mark")
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    held = [i for i in run.sim.world.holder if i.startswith("ruler:")]
    assert any(run.sim.world.holder[i] == "mark" for i in held), trace.summary
    assert not any(r.refused for r in trace.actions()), trace.summary
