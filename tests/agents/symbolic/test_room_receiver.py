"""A room as the destination of a delivery (issue 23): "take my stapler to the meeting room".

The robot hands things to people, so a room a thing is taken to is where it goes, never an
errand asked of the room (the meeting room, a facility whose service nobody runs, was refused:
"Sorry, I can't help with the meeting room"; ``carried_to``). Whoever the message says needs
the thing, or says is in that room, receives it (``room_receiver``), and the consent guard
reads the same words as naming them; with nobody said, who there should get it is asked in
one question that names the room and the people there by name.
"""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import SendQR
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import answered_reader, frame_reader

_DEFAULT = frame_reader(default_office, "wang")  # Wang Fang owns a stapler
_HARBOUR = frame_reader(harbour_office, "will")  # Will Tanaka owns a calculator
_DEFAULT_ANSWERED = answered_reader(default_office, "wang")
_HARBOUR_ANSWERED = answered_reader(harbour_office, "will")

_REFUSED = "can't help with"
_WHO_THERE = "who there should get it?"


@pytest.mark.parametrize(
    ("text", "who"),
    [
        # the class's analogues
        (
            "Zhang needs my stapler for the review. Can you take it over to the meeting room?",
            "zhang",
        ),
        ("Zhang needs my stapler. take it to the meeting room please", "zhang"),
        (
            "Zhang needs my stapler for the review. bring it to Zhang, he's in the meeting room",
            "zhang",
        ),
        # variants: another room, another way to say the need, presence instead of need
        ("Hu is after my stapler, drop it into the print room", "hu"),
        ("Lin could do with my stapler. can you run it over to the boardroom?", "lin"),
        ("Zhou is in the meeting room. Can you take my stapler over to the meeting room?", "zhou"),
        ("Gao's in the conference room, take my stapler to the conference room", "gao"),
    ],
)
def test_default_the_one_said_to_need_it_or_be_there_receives(text: str, who: str) -> None:
    frame = _DEFAULT(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", "stapler", "wang", who)], frame


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("Grace needs my calculator. take it to the lounge please", "grace"),
        ("Mark needs my calculator for the workshop. can you take it over to the kitchen?", "mark"),
        ("Dawn is in the lounge. bring my calculator over to the lounge", "dawn"),
        ("Grace is after my calculator, drop it into the copy room", "grace"),
    ],
)
def test_harbour_the_one_said_to_need_it_or_be_there_receives(text: str, who: str) -> None:
    frame = _HARBOUR(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", "calculator", "will", who)], frame


@pytest.mark.parametrize(
    ("reader", "text", "room", "there"),
    [
        (_DEFAULT, "take my stapler to the meeting room", "meeting room", "Mao Jun or Zhou Yan"),
        (_DEFAULT, "Can you take my stapler over to the meeting room?", "meeting room", "Zhou Yan"),
        (_DEFAULT, "could you carry my stapler into the boardroom", "boardroom", "Mao Jun"),
        (_DEFAULT, "take my stapler to the kitchenette", "kitchenette", "Hu Jing"),
        (_HARBOUR, "take my calculator to the lounge", "lounge", "Joy Achebe"),
        (_HARBOUR, "Can you run my calculator over to the lounge?", "lounge", "Joy Achebe"),
        (_HARBOUR, "bring my calculator to the kitchen", "kitchen", "Hope Mensah"),
    ],
)
def test_with_nobody_said_who_there_is_asked_by_name(
    reader: object, text: str, room: str, there: str
) -> None:
    frame = reader(text)  # type: ignore[operator]
    assert not frame.tasks, frame
    question = frame.question or ""
    assert _REFUSED not in question, question
    assert f"to the {room}" in question and _WHO_THERE in question, question
    assert there in question, question
    assert "_" not in question, question  # names, never ids


@pytest.mark.parametrize(
    ("reader", "text", "answer", "item", "owner", "who"),
    [
        (
            _DEFAULT_ANSWERED,
            "take my stapler to the meeting room",
            "Zhang",
            "stapler",
            "wang",
            "zhang",
        ),
        (_HARBOUR_ANSWERED, "take my calculator to the lounge", "Joy", "calculator", "will", "joy"),
    ],
)
def test_the_answer_names_who_gets_it(
    reader: object, text: str, answer: str, item: str, owner: str, who: str
) -> None:
    frame = reader(text, [answer])  # type: ignore[operator]
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", item, owner, who)], frame


@pytest.mark.parametrize(
    "text",
    [
        "Zhang needs my stapler. Hu needs it too. take it to the meeting room",  # two: asked
        "take my stapler to Desk 6",  # the requester's own desk: never carried back to them
    ],
)
def test_undecided_is_asked(text: str) -> None:
    frame = _DEFAULT(text)
    assert not frame.tasks and frame.question, frame


def test_the_guard_reads_the_one_said_to_need_it_as_named() -> None:
    office = default_office()
    said = "Zhang needs my stapler. take it to the meeting room please"
    assert "zhang" in named_recipients(office, memory("wang", said))
    there = "Zhou is in the meeting room. take my stapler to the meeting room"
    assert "zhou" in named_recipients(office, memory("wang", there))
    # no room the thing goes to: a need alone names nobody to receive (a wish, a reason)
    assert "zhang" not in named_recipients(office, memory("wang", "Zhang needs a stapler"))
    # two said to need it decide nothing
    two = "Zhang needs my stapler. Hu needs it too. take it to the meeting room"
    assert not named_recipients(office, memory("wang", two)) & {"zhang", "hu"}


@pytest.mark.parametrize(
    ("office", "who", "text", "receiver", "item"),
    [
        (
            default_office,
            "wang",
            "Zhang needs my stapler for the review. Can you take it over to the meeting room?",
            "zhang",
            "stapler:wang",
        ),
        (
            harbour_office,
            "will",
            "Grace needs my calculator. take it to the lounge please",
            "grace",
            "calculator:will",
        ),
    ],
)
async def test_end_to_end_the_code_goes_to_the_one_who_needs_it(
    office: object, who: str, text: str, receiver: str, item: str
) -> None:
    run = await run_instruction(office(), who, text)  # type: ignore[operator]
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    assert run.sim.world.holder[item] == receiver, trace.summary
    codes = [r.action for r in trace.actions() if isinstance(r.action, SendQR) and not r.refused]
    assert any(a.contact == receiver and a.purpose == "collect" for a in codes), codes
    assert not any(r.refused for r in trace.actions()), trace.summary


@pytest.mark.parametrize(
    ("text", "got"),
    [
        # a name after "to" still receives, at their desk, as before
        (
            "take my stapler to Zhang in the meeting room",
            [("transfer", "stapler", "wang", "zhang")],
        ),
        ("leave my stapler on Zhang's desk", [("transfer", "stapler", "wang", "zhang")]),
        (
            "take my stapler to the meeting room for Zhang",
            [("transfer", "stapler", "wang", "zhang")],
        ),
    ],
)
def test_must_not_change_a_named_recipient(text: str, got: list[tuple[str, ...]]) -> None:
    frame = _DEFAULT(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == got, frame


@pytest.mark.parametrize(
    ("reader", "text"),
    [(_DEFAULT, "book the meeting room"), (_HARBOUR, "book the lounge")],
)
def test_must_not_change_an_errand_asked_of_the_room(reader: object, text: str) -> None:
    """Nothing is carried there: the room's service is what is asked, and declined."""
    frame = reader(text)  # type: ignore[operator]
    assert not frame.tasks and frame.decline, frame
