"""A request over every one of a kind that colleagues own ("wipe all the drives", "bring me
every stapler", "collect everyone's mugs") is declined in words: each owner's yes is asked in
their own chat, one thing at a time. It had been read as the requester's own one, so a
request to wipe all the drives in a vault wiped the requester's drive (a wrong physical
action in a blind round). The speaker's own ("all my ..."), files, made things and a
quantifier that takes in no item are read as before.

A complaint told with "'s" for "has" and a quantifier after the participle ("someone's eaten
half my lunch from the fridge") is a statement: it had fetched the lunch."""

from __future__ import annotations

import pytest
from _offices import parser
from symbolic_run import run_instruction

from assistantx.core.actions import Move
from assistantx.core.office import load_office
from helpers.dataset_offices import DEFAULT_FILE


def _frame(text: str, who: str = "wu", office: str = "default"):  # type: ignore[no-untyped-def]
    return parser(office).parse(text, who)


@pytest.mark.parametrize(
    ("office", "text"),
    [
        ("default", "bring me every stapler in the office"),
        ("default", "collect everyone's mugs and put them in the kitchen"),
        ("default", "take all the seals to the meeting room"),
        ("default", "I need all of the staplers on this floor"),
        ("default", "could you grab all the old staplers for me"),
        ("mail_room", "shred all the drafts in the mail room tonight, we need the space"),
        ("mail_room", "please bind every document on the shelf"),
        ("mail_room", "fax each document in the tray"),
    ],
)
def test_every_one_of_a_kind_is_declined_in_words(office: str, text: str) -> None:
    frame = _frame(text, "pat" if office == "mail_room" else "wu", office)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "Tell me whose" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # the quantifier takes in no item, or the speaker's own, or a file
        ("thanks all, bring me a stapler", [("transfer", "stapler", None, "wu")]),
        ("print all the files", [("print", "file", "wu", "wu")]),
        ("bring me Zhang's stapler", [("transfer", "stapler", "zhang", "wu")]),
        ("the staplers are all broken, bring me one", [("transfer", "stapler", None, "wu")]),
    ],
)
def test_what_takes_in_no_colleagues_things_is_read_as_before(
    text: str, tasks: list[tuple[str, str, str | None, str]]
) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == tasks


def test_all_of_the_speakers_own_is_not_declined_as_everyones() -> None:
    frame = _frame("shred all my drafts please", "pat", "mail_room")
    assert frame.decline is None or "Tell me whose" not in frame.decline, frame


@pytest.mark.parametrize(
    "text",
    [
        "ugh, someone's eaten half my lunch from the fridge again",
        "someone's taken all the staplers from my desk",
        "someone's nicked both my staplers again",
        "Zhang's borrowed half my pens",
    ],
)
def test_a_has_contracted_before_a_quantified_object_is_told_not_asked(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame


def test_a_bare_possessive_before_an_adjective_still_owns_the_thing() -> None:
    frame = _frame("bring me Zhang's broken stapler")
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", "stapler", "zhang")]


async def test_end_to_end_every_stapler_moves_nothing_and_asks_no_one() -> None:
    run = await run_instruction(load_office(DEFAULT_FILE), "wu", "bring me every stapler")
    trace = run.stm.trace
    assert not any(isinstance(r.action, Move) for r in trace.actions()), trace.summary
    contacts = {getattr(r.action, "contact", None) for r in trace.actions()} - {None}
    assert contacts <= {"wu"}, trace.summary
