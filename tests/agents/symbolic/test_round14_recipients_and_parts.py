"""Blind round 14's reader classes about who receives and which parts a request has, on
sentences of our own against a ceramics studio's design office no sentence was written for
(``helpers.kilnworks``; the round's own office and sentences were never read): a title alias
with its article ("the Provost"), a person's own place as where they receive ("leave one at
her desk"), a colleague's item asked for by "theirs", a part of a request that cannot be
resolved, and "for her" after a printed product."""

from __future__ import annotations

import functools

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.task_schema import TaskFrame
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.kilnworks import kilnworks


@functools.cache
def _parser() -> InstructionParser:
    return InstructionParser(kilnworks())


def _frame(text: str, who: str = "kit") -> TaskFrame:
    return _parser().parse(text, who)


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient, t.actor) for t in frame.tasks]


# -- 1. a title alias with its article is the person --------------------------------------


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        ("print my agenda and give it to the Provost", [("print", "agenda", "oona", None)]),
        ("print my agenda for the Provost", [("print", "agenda", "oona", None)]),
        ("take my report to the provost please", [("transfer", "report", "oona", None)]),
        ("get the Provost to sign my report", [("sign", "report", "kit", "oona")]),
        ("bring me the Provost's calculator", [("transfer", "calculator", "kit", None)]),
    ],
)
def test_a_title_declared_with_its_article_names_the_person(
    text: str, tasks: list[tuple[str, str | None, str | None, str | None]]
) -> None:
    """ "the Provost" is declared for Oona Pike: written with its article it is her, as
    recipient, signer or owner; never "Do you mean Oona Pike, or the provost?"."""
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert _tasks(frame) == tasks


def test_the_owner_named_by_a_title_alias_is_the_owner() -> None:
    frame = _frame("bring me the Provost's calculator")
    assert [t.owner for t in frame.tasks] == ["oona"]


@pytest.mark.parametrize(
    "text", ["print my agenda and give it to the Provost", "take my report to the Provost"]
)
def test_the_guard_knows_the_title_alias_as_the_recipient(text: str) -> None:
    assert named_recipients(kilnworks(), memory("kit", text)) == {"oona"}


@pytest.mark.parametrize(
    "text", ["what does a provost do?", "is there a provost here?", "who is the provost?"]
)
def test_a_question_about_the_title_moves_nothing(text: str) -> None:
    """Near-miss: a question naming the title is still a question."""
    assert _frame(text).tasks == []


async def test_a_printout_for_the_title_alias_is_handed_to_her() -> None:
    run = await run_instruction(kilnworks(), "kit", "print my agenda and give it to the Provost")
    handed = [
        (r.action.contact, r.action.purpose)
        for r in run.stm.trace.actions()
        if r.action.type == "send_qr" and not r.refused
    ]
    assert ("oona", "collect") in handed
    assert not [r for r in run.stm.trace.actions() if r.refused]


# -- 2. a person's own place names them as the recipient, for the reader and the guard ----

AT_THEIR_PLACE = [
    ("Sunniva wants a hole punch, drop one at her desk", "sunniva"),
    ("Sunniva wants a hole punch. Could you drop one at her desk?", "sunniva"),
    ("Teodor needs a calculator, could you drop one on his desk", "teodor"),
    ("Bram asked for a hole punch, please put one in his office", "bram"),
    ("drop a hole punch on Sunniva's desk", "sunniva"),
    ("leave my calculator in Bram's tray", "bram"),
]


@pytest.mark.parametrize(("text", "to"), AT_THEIR_PLACE)
def test_her_place_makes_her_the_recipient(text: str, to: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [t.recipient for t in frame.tasks] == [to]


@pytest.mark.parametrize(
    "text",
    [
        *(text for text, _ in AT_THEIR_PLACE),
        "print my agenda and give it to the Provost",
        "Sunniva asked for the agenda, print it for her",
        "bring Teodor my calculator",
        "can you drop my calculator off for Bram",
    ],
)
def test_whoever_the_reader_hands_over_to_the_guard_was_told_of(text: str) -> None:
    """One rule (``core.receiving_place``) for the reader and the guard: every recipient of
    the reader's frame other than the requester is someone the guard counts as named."""
    frame = _frame(text)
    receivers = {t.recipient for t in frame.tasks} - {"kit", None}
    assert receivers, frame
    assert receivers <= named_recipients(kilnworks(), memory("kit", text)), text


@pytest.mark.parametrize(
    "text",
    [
        "Sunniva and Bram want a hole punch, drop one at her desk",  # whose desk?
        "drop a hole punch at her desk",  # nobody named
    ],
)
def test_a_place_pronoun_with_no_one_person_before_it_is_asked(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None


@pytest.mark.parametrize(
    ("text", "named"),
    [
        ("bring me the hole punch from Sunniva's desk", set()),  # a source, not a recipient
        ("Sunniva wants a hole punch", set()),  # a wisher only
        ("bring me Sunniva's calculator", set()),  # an owner only
        ("Sunniva and Bram want a hole punch, drop one at her desk", set()),
    ],
)
def test_the_guard_names_no_one_else_from_a_place(text: str, named: set[str]) -> None:
    """Near-misses: a place one takes from, a wish, an owner, or an ambiguous "her" name no
    recipient for the guard."""
    assert named_recipients(kilnworks(), memory("kit", text)) == named


async def test_the_item_left_at_her_desk_is_handed_to_her() -> None:
    """The run that fetched a colleague's hole punch and then had the hand-over refused ("not
    someone you named to receive it") now hands it over."""
    run = await run_instruction(
        kilnworks(), "kit", "Sunniva wants a hole punch, drop one at her desk"
    )
    assert not [r for r in run.stm.trace.actions() if r.refused]
    handed = [
        (r.action.contact, r.action.purpose)
        for r in run.stm.trace.actions()
        if r.action.type == "send_qr"
    ]
    assert handed[-1] == ("sunniva", "collect")
