"""Issue #23, fixer fix97h class 1: "mark needs my ruler, can you take it over": the thing
"it" taken over/round/across to nobody named goes to the one colleague said to need it, also
when that name is written lower-case and is an English word. The reader and the consent
guard (``runtime.recipients``) must agree, or the guard refuses the hand-over the reader
planned ("not someone you named to receive")."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.parser import shared_parser
from assistantx.core.office import Office
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.dataset_offices import default_office, harbour_office


def _read(office: Office, who: str, text: str) -> tuple[set[str], list[tuple[str | None, ...]]]:
    frame = shared_parser(office).parse_with_answers(text, who, [])
    tasks = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    return named_recipients(office, memory(who, text)), tasks


@pytest.mark.parametrize(
    ("office", "who", "text", "item", "receiver"),
    [
        # the class's analogues (harbour: Mark, Will are names and words)
        ("harbour", "rose", "mark needs my ruler for the induction, can you take it over",
         "ruler", "mark"),
        ("harbour", "rose", "will needs my calculator for the stock take, could you take it over",
         "calculator", "will"),
        # variants of our own: other names, things, verbs and particles
        ("harbour", "rose", "bill needs my calculator for the audit, can you bring it round",
         "calculator", "bill"),
        ("harbour", "rose", "hope needs my ruler for the quiz, could you carry it across?",
         "ruler", "hope"),
        ("harbour", "rose", "joy needs my tape for the launch, can you pop it round?",
         "tape", "joy"),
        ("default", "lee", "Chen needs my stapler for the meeting, can you take it over",
         "stapler", "chen"),
    ],
)  # fmt: skip
def test_it_taken_over_goes_to_the_one_said_to_need_it(
    office: str, who: str, text: str, item: str, receiver: str
) -> None:
    here = harbour_office() if office == "harbour" else default_office()
    guard, tasks = _read(here, who, text)
    assert tasks == [("transfer", item, who, receiver)]
    assert guard == {receiver}


def test_a_receiver_said_after_the_particle_is_the_receiver() -> None:
    # neighbour: "take it over to mark" names its own receiver, not the one who needs it
    guard, tasks = _read(harbour_office(), "rose", "will needs my ruler, take it over to mark")
    assert guard == {"mark"}
    assert tasks == [("transfer", "ruler", "rose", "mark")]


@pytest.mark.parametrize(
    "text",
    [
        "mark my ruler as lost",  # "mark" the verb
        "will you take my ruler over?",  # "will" the modal: nobody needs it
        "June needs a ruler",  # a need alone, nothing taken
        "mark my calculator as broken and take it over",
    ],
)
def test_neighbours_name_no_receiver(text: str) -> None:
    guard, _ = _read(harbour_office(), "rose", text)
    assert guard == set()


def test_two_said_to_need_it_decide_nothing_for_the_guard() -> None:
    guard, _ = _read(
        harbour_office(), "rose", "mark needs my ruler and will needs it too, take it over"
    )
    assert guard == set()
