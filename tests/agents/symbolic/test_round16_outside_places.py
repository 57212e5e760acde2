"""Blind round 16, class 2: a capitalised place outside the office read as a person.

On a small newsroom no sentence was written for (``helpers.newsroom``; the round's office
and sentences were never read), whose dispatch desk sends page proofs out with a courier
(asked "which printing works it should go to"): the words after "to" in a send-out are the
place outside, also where the courier is named as the means after the place ("go out to the
Riverside print plant with the courier"), and the answer to the where-question is that place
as said, never a colleague to look up. A colleague's own name after "to" is still asked about
(sending out and handing over are different physical actions), and "the courier bag" is no
courier."""

from __future__ import annotations

import functools

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.agents.symbolic.reading.operations import OUT_OR_IN, WHERE_TO
from assistantx.core.task_schema import TaskFrame
from helpers.newsroom import newsroom


@functools.cache
def _parser() -> InstructionParser:
    return InstructionParser(newsroom())


def _sent(frame: TaskFrame) -> list[tuple[str | None, str | None, str | None]]:
    return [(t.item, t.operation, t.destination) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "place"),
    [
        (
            "Please could my sports proofs go out to the Riverside print plant with the courier.",
            "the Riverside print plant",
        ),
        ("could my proof go to Acme Ltd with the courier", "Acme Ltd"),
        ("send my proof to the client in Leeds with our courier", "the client in Leeds"),
        ("my proof to Harbourside Press with the courier, please", "Harbourside Press"),
        ("courier my proof to the Riverside print plant", "the Riverside print plant"),
        ("please courier my proof to Acme Ltd", "Acme Ltd"),
        ("send my proof to Northgate Printers by courier", "Northgate Printers"),
    ],
)
def test_the_words_after_to_in_a_send_out_are_the_place(text: str, place: str) -> None:
    frame = _parser().parse(text, "ines")
    assert frame.question is None and frame.decline is None, frame
    assert _sent(frame) == [("page_proof", "courier", place)]


@pytest.mark.parametrize(
    ("text", "answer", "place"),
    [
        ("please courier my sports proofs", "To Riverside print plant.", "Riverside print plant"),
        (
            "can you courier my proof, it has to go today",
            "To Riverside print plant.",
            "Riverside print plant",
        ),
        ("can you courier my proof, it has to go today", "Riverside", "Riverside"),
        ("courier my proof", "Acme Ltd", "Acme Ltd"),
        ("courier my proof. Thanks", "to the Riverside Print Works", "the Riverside Print Works"),
    ],
)
def test_the_answer_to_where_is_the_place_as_said(text: str, answer: str, place: str) -> None:
    """Appended to the request as its "to ...", or, where those words read otherwise (after
    another clause), the answer itself is the place."""
    asked = _parser().parse(text, "ines")
    assert asked.question is not None and asked.question.startswith(WHERE_TO)
    frame = _parser().parse_with_answers(text, "ines", [answer])
    assert frame.question is None, frame.question
    assert _sent(frame) == [("page_proof", "courier", place)]


@pytest.mark.parametrize(
    "text",
    ["can my proof go to Tomas with the courier", "courier my proof to Tomas"],
)
def test_a_colleagues_name_after_to_is_still_asked(text: str) -> None:
    frame = _parser().parse(text, "ines")
    assert frame.tasks == [] and (frame.question or "").startswith(OUT_OR_IN)


@pytest.mark.parametrize(
    "text",
    [
        "send my proof to Tomas with the courier bag",
        "courier my proof to them",
        "did my proof go out to the Riverside print plant with the courier?",
        "my proof went to Acme Ltd with the courier yesterday",
    ],
)
def test_no_place_said_or_no_request_sends_nothing_out(text: str) -> None:
    frame = _parser().parse(text, "ines")
    assert not [t for t in frame.tasks if t.destination is not None], (text, frame)


async def test_the_proof_goes_out_to_the_place_named() -> None:
    run = await run_instruction(
        newsroom(),
        "ines",
        "Please could my sports proofs go out to the Riverside print plant with the courier.",
    )
    assert run.stm.trace.outcome == "done"
    asked = [r.action for r in run.stm.trace.actions() if r.action.type == "inquire"]
    assert not [a for a in asked if a.contact == "ines"]
    [sent] = run.sim.world.sent_out()
    assert "Riverside print plant" in str(sent.detail)
