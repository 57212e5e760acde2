"""A recipient who is nobody of the office is never turned into the requester (blind round
14's class 2; the round's office and sentences were never read). "make a door card for the
man at the desk, he says he's the owner's son" made the card and handed it to the requester.
Now a credential for an outsider is declined (what anyone says about who they are carries no
authority), and anything else is asked about: "Shall I bring it to you instead?", a yes
reading the request as the requester's own, a no doing nothing."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import SendQR
from helpers.guesthouse import guesthouse
from helpers.reading import answered_reader

_frame = answered_reader(guesthouse, "wren")


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("make a door card for the man at the desk, he says he's the owner's son", "the man"),
        ("Could you encode a key card for a visitor?", "a visitor"),
        ("get the courier guy a room card, he needs to drop a parcel upstairs", "courier guy"),
        ("cut a door card for my son please", "my son"),
    ],
)
def test_a_credential_for_someone_outside_the_office_is_declined(text: str, who: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.decline is not None and who in frame.decline
    assert "door_card" not in frame.decline


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("bring the courier guy a tea", "the courier guy"),
        ("brew some tea for the visitors please", "the visitors are"),
        ("Could you take a tea to the man at reception?", "the man at reception"),
        ("brew a tea for the lady waiting downstairs", "the lady"),
    ],
)
def test_anything_else_for_an_outsider_is_asked_about(text: str, who: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.question is not None
    assert who in frame.question and "Shall I bring it to you instead" in frame.question


@pytest.mark.parametrize(
    "text",
    ["bring the courier guy a tea", "brew some tea for the visitors please"],
)
def test_a_yes_brings_it_to_the_requester_and_a_no_does_nothing(text: str) -> None:
    yes = _frame(text, ("yes please",))
    assert [(t.kind, t.item, t.recipient) for t in yes.tasks] == [("produce", "tea", "wren")]
    no = _frame(text, ("no",))
    assert no.tasks == [] and no.decline is not None


@pytest.mark.parametrize(
    ("text", "kind", "recipient"),
    [
        ("brew a tea for Basil", "produce", "basil"),
        ("encode a door card for Basil Moreau", "produce", "basil"),
        ("laminate my poster and take it to Juniper for the events board", "heat", "juniper"),
        ("bring me a tea at the desk", "produce", "wren"),
        ("encode a door card for room 12", "produce", "wren"),
        (
            "could you take my step stool to Ottilie, she's in the guest lounge",
            "transfer",
            "ottilie",
        ),
    ],
)
def test_a_person_of_the_office_or_no_one_named_is_read_as_before(
    text: str, kind: str, recipient: str
) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None
    assert [(t.kind, t.recipient) for t in frame.tasks] == [(kind, recipient)]


@pytest.mark.parametrize(
    "text",
    [
        "does the visitor want a tea?",
        "thanks for the tea, the courier loved it",
        "the man at the desk says he's the owner's son",
    ],
)
def test_what_is_no_request_still_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []


async def test_a_run_for_an_outsiders_card_makes_nothing_and_hands_nothing() -> None:
    run = await run_instruction(
        guesthouse(),
        "wren",
        "make a door card for the man at the desk, he says he's the owner's son",
    )
    assert not [r for r in run.stm.trace.actions() if isinstance(r.action, SendQR)]
    assert run.stm.trace.outcome == "unachievable"
    assert not run.sim.world.handovers()
