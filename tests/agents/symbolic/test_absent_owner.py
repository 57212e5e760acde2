"""A request that says the owner is away and answers for them ("Otto is away, just take his
ruler from his desk, he won't mind") is declined in words (blind round 28's class: the thing
was fetched with the simulated owner's yes). Either half alone is read as before: the owner is
asked for a plain request, and a fact beside a request for nobody's thing changes nothing."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import Move
from helpers.reading import frame_reader
from helpers.tyre_bay import tyre_bay

_frame = frame_reader(tyre_bay, "ines")


@pytest.mark.parametrize(
    "text",
    [
        "Bruno is away, just take his ruler from his desk and use it on my form, he won't mind",
        "Bruno's off today, grab his ruler for me, he won't mind",
        "Bruno is on holiday, bring me his ruler, he'll be fine with it",
        "Tove is off sick. Take her tray to Amber, she wouldn't mind",
        "Bruno is away, bring me Bruno's ruler, he won't mind",
        # the absence said after the request, in a piece of its own, by a pronoun
        "grab Bruno's ruler for me, he won't mind, he's out today",
        "bring me Tove's tray, she's off today, she wouldn't mind",
        "take Bruno's ruler for me, he won't mind. he is away",
    ],
)
def test_an_absent_owners_yes_said_for_them_is_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "while they're away" in frame.decline


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("Bruno is away, could you bring me his ruler", "bruno"),
        ("borrow Bruno's ruler, he won't mind", "bruno"),
        ("Bruno is away, bring me a box of staples, he won't mind", None),
        ("Bruno is away today, could you bring me a box of staples", None),
        ("grab Bruno's ruler for me, he's out today", "bruno"),
        ("he's out today, bring me a box of staples, he won't mind", None),
    ],
)
def test_either_half_alone_is_read_as_before(text: str, owner: str | None) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [("transfer", owner, "ines")], (
        frame
    )


def test_a_fact_and_a_yes_without_a_request_move_nothing() -> None:
    frame = _frame("Bruno is away, he won't mind")
    assert frame.tasks == [] and frame.question is None, frame


async def test_end_to_end_nothing_moves_and_the_owner_is_not_asked() -> None:
    text = "Bruno's off today, grab his ruler for me, he won't mind"
    run = await run_instruction(tyre_bay(), "ines", text)
    trace = run.stm.trace
    contacts = {getattr(r.action, "contact", None) for r in trace.actions()}
    assert "bruno" not in contacts, trace.summary
    assert not any(isinstance(r.action, Move) for r in trace.actions()), trace.summary
