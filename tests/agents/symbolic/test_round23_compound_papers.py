"""Blind rounds 23 and 24, class 1: work that needs a paper one signs, its object a compound
whose first part names that paper ("sign this contract extension"), is done on the
requester's one such paper. On sentences of our own against a training ground no sentence was
written for (the rounds' office and sentences were never read). Other work on a compound
still names its head, never the item."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.reading import frame_reader
from helpers.training_ground import training_ground

_frame = frame_reader(training_ground, "dele")

Row = tuple[str, str | None, str | None, str, str | None]

_SIGNED_BY_RHYS = [("sign", "contract", "dele", "dele", "rhys")]


def _tasks(text: str, who: str = "dele") -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient, t.actor) for t in _frame(text, who).tasks]


@pytest.mark.parametrize(
    "text",
    [
        "Can you ask the Gaffer to sign this contract extension and bring it back to me? "
        "The agent is waiting on it.",
        "can you get Rhys to sign the contract extension please",
        "get this contract renewal signed by the gaffer",
        "could the gaffer sign off the contract extension for me",
        "can you get Rhys to sign my contract extension please",
        "get the gaffer to sign my contract",
    ],
)
def test_a_compound_named_after_my_one_paper_is_that_paper(text: str) -> None:
    assert _tasks(text) == _SIGNED_BY_RHYS


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("can you get Rhys to sign this contract extension please", "owen"),  # owns none
        ("can you get Rhys to sign the stopwatch list please", "dele"),  # another item
    ],
)
def test_no_paper_of_mine_or_another_first_part_still_asks(text: str, who: str) -> None:
    frame = _frame(text, who)
    assert frame.tasks == []
    assert frame.question is not None and "Which item" in frame.question


@pytest.mark.parametrize(
    "text",
    [
        "bring me the contract extension",  # no signing: the head names a thing
        "is the contract extension signed yet?",
        "thanks for getting the contract extension signed",
        "don't get the contract extension signed",
    ],
)
def test_other_work_a_question_thanks_or_negation_moves_no_contract(text: str) -> None:
    assert _tasks(text) == []


def test_my_scouting_report_file_is_still_the_file() -> None:
    assert _tasks("send my scouting file to Rhys") == [
        ("send_file", "scouting_file", "dele", "rhys", None)
    ]


async def test_the_contract_goes_to_the_gaffer_and_back() -> None:
    run = await run_instruction(
        training_ground(),
        "dele",
        "Can you ask the Gaffer to sign this contract extension and bring it back to me?",
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    # main asked "Which item do you mean to be signed?" and moved nothing
    assert "send_qr" in run.actions, run.actions
