"""The colleague asked to make "one" after the speaker's own need is its maker, not whom it is
for (``reading.asked_maker``): "I need a coffee. can Gao knock one up?" is a coffee for the
speaker, made by Gao where Gao keeps a facility that makes it. Someone named after the verb
("make Gao a coffee", "make Sun one") is still whom it is for."""

from __future__ import annotations

import pytest
from _offices import office, parser
from symbolic_run import run_instruction


def _read(name: str, text: str, who: str) -> list[tuple[str, str | None, str, str | None]]:
    frame = parser(name).parse(text, who)
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.recipient, t.actor) for t in frame.tasks]


@pytest.mark.parametrize(
    ("name", "who", "text", "tasks"),
    [
        # the class's analogue
        (
            "default",
            "lee",
            "I'm on the phones and need a coffee. can Gao knock one up?",
            [("produce", "coffee", "lee", "gao")],
        ),
        # other verbs, other keepers, other products
        (
            "default",
            "wang",
            "I need a coffee. can Sun whip one up?",
            [("produce", "coffee", "wang", "sun")],
        ),
        (
            "default",
            "lee",
            "dying for a coffee. could Gao sort one out?",
            [("produce", "coffee", "lee", "gao")],
        ),
        (
            "default",
            "lee",
            "I need some water. could Zheng pour one?",
            [("produce", "water", "lee", "zheng")],
        ),
        (
            "harbour",
            "mark",
            "I need a tea. could Ken whip one up for me?",
            [("produce", "tea", "mark", "ken")],
        ),
    ],
)
def test_the_one_asked_makes_it_for_the_speaker(
    name: str, who: str, text: str, tasks: list[tuple[str, str | None, str, str | None]]
) -> None:
    assert _read(name, text, who) == tasks


def test_one_who_keeps_no_facility_that_makes_it_is_said_and_asked() -> None:
    """Lin keeps no coffee machine: said, and asked before a keeper makes it instead; a yes
    makes it for the speaker with a keeper (``named_maker``, test_named_maker.py)."""
    text = "need a coffee, could Lin make one?"
    frame = parser("default").parse(text, "lee")
    assert not frame.tasks, frame
    assert (frame.question or "").startswith("Lin Tao doesn't look after the coffee machine")
    yes = parser("default").parse_with_answers(text, "lee", ["yes"])
    assert [(t.kind, t.item, t.recipient, t.actor) for t in yes.tasks] == [
        ("produce", "coffee", "lee", None)
    ], yes


@pytest.mark.parametrize(
    ("name", "who", "text", "tasks"),
    [
        # must not change: the colleague named after the verb is whom it is for
        ("default", "lee", "can you make Gao a coffee", [("produce", "coffee", "gao", None)]),
        ("harbour", "mark", "could you make Ken a tea", [("produce", "tea", "ken", None)]),
        (
            "default",
            "lee",
            "I need a coffee. can Gao make Sun one?",
            [("produce", "coffee", "lee", None), ("produce", "coffee", "sun", None)],
        ),
        # "have one" is receiving, not making: one more, for them
        (
            "default",
            "lee",
            "I need a coffee. can Gao have one too?",
            [("produce", "coffee", "lee", None), ("produce", "coffee", "gao", None)],
        ),
    ],
)
def test_must_not_change(
    name: str, who: str, text: str, tasks: list[tuple[str, str | None, str, str | None]]
) -> None:
    assert _read(name, text, who) == tasks


async def test_end_to_end_the_maker_makes_it_and_the_speaker_gets_it() -> None:
    run = await run_instruction(office("default"), "lee", "I need a coffee. can Sun whip one up?")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    handed = [(e.detail["item"], e.detail["to"]) for e in run.sim.world.handovers()]
    assert handed and all(to == "lee" for _, to in handed), handed
    assert "Sun Li" in run.stm.trace.summary, run.stm.trace.summary
