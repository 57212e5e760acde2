"""Fixer fix60g class 2: vague work said as a participle right after the requester's own thing,
under a verb of needing or getting ("I need my bowl sorted before the crit", "can you get my
contract dealt with today"), where two or more of the office's services take the thing, is
asked by naming them; main read the need or the "get" as a fetch and brought the thing back
(or asked who should get it). Where one service takes it, or a move is said, as before."""

from __future__ import annotations

import pytest

from helpers.airside_kitchen import airside_kitchen
from helpers.dataset_offices import default_office
from helpers.reading import answered_reader, frame_reader

_kitchen = frame_reader(airside_kitchen, "odile")
_default = frame_reader(default_office, "lee")
_answered = answered_reader(default_office, "lee")

_PREP = "Which should I do with your prep: vacuum seal or blast chill?"
_DOCUMENT = "Which should I do with your document: copy, sign or seal?"


@pytest.mark.parametrize(
    "text",
    [
        "I need my prep sorted before the meeting",
        "can you get my prep dealt with today",
        "I need my prep taken care of",
        "I need my prep done before service",
        "can you get my prep sorted",
    ],
)
def test_vague_work_after_own_thing_two_services_take_is_asked(text: str) -> None:
    frame = _kitchen(text)
    assert frame.tasks == [] and frame.question == _PREP


@pytest.mark.parametrize(
    "text",
    [
        "I need my document sorted before the meeting",
        "can you get my contract dealt with today",
        "deal with my contract please",
        "could you deal with my document",
    ],
)
def test_the_signable_paper_counts_signing_and_sealing(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.question == _DOCUMENT


@pytest.mark.parametrize(("answer", "operation"), [("copy", "copy"), ("seal it", "seal")])
def test_the_answer_names_the_work(answer: str, operation: str) -> None:
    frame = _answered("I need my document sorted before the meeting", [answer])
    assert [(t.operation or t.kind, t.item) for t in frame.tasks] == [(operation, "document")]


def test_sign_answered_asks_who_signs() -> None:
    frame = _answered("can you get my contract dealt with today", ["sign"])
    assert frame.question == "Who should sign your document? Please tell me their name."


def test_one_service_keeps_its_question() -> None:
    """Must not change: where only heating takes lunch, fetch or heat is asked as before."""
    assert _default("I need my lunch sorted").question == (
        "Shall I bring you your lunch, or have it heated?"
    )
    assert _kitchen("I need my trimmings sorted").question == (
        "Shall I bring you your trimmings, or have it digested?"
    )


@pytest.mark.parametrize(
    ("text", "question"),
    [
        (
            "I need my stapler back",
            "As far as I know, you have no stapler of your own here. Where is it?",
        ),
        ("get my contract signed", "Who should sign your document? Please tell me their name."),
        ("bring me my document", "Where is your document? As far as I know you have it with you."),
    ],
)
def test_a_move_or_named_work_is_read_as_before(text: str, question: str) -> None:
    assert _default(text).question == question


def test_a_move_said_with_need_is_no_question_of_work() -> None:
    assert _kitchen("I need my prep back").question != _PREP
