"""A service asked for in the passive, "can/could <thing> be/get [prefix-]<participle>", is
a request for the office's work on the speaker's thing, which comes back to them (round
160, class 1; ``reading.passive_service``); a question about the thing's state or a
facility's is still answered in words, and moves nothing."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of

from helpers.reading import frame_reader
from helpers.repro_room import repro_room

_repro = frame_reader(repro_room, "bram")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # the class's analogues
        ("could my report be spiral-bound for me?", ("heat", "report", "bram", "bram", "bind")),
        ("can these proofs get laminated?", ("heat", "proofs", "bram", "bram", "laminate")),
        ("could the report be comb-bound?", ("heat", "report", "bram", "bram", "bind")),
        # variants: "be" with no prefix, a "for me", another prefix
        ("could the proofs be laminated?", ("heat", "proofs", "bram", "bram", "laminate")),
        ("could the report be bound please?", ("heat", "report", "bram", "bram", "bind")),
        (
            "could the proofs be heat-laminated for me?",
            ("heat", "proofs", "bram", "bram", "laminate"),
        ),
    ],
)
def test_a_passive_service_is_asked_for(text: str, expected: tuple[str, ...]) -> None:
    frame = _repro(text)
    assert [(t.kind, t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [
        expected
    ], frame


@pytest.mark.parametrize(
    ("office", "requester", "text", "expected"),
    [
        ("harbour", "may", "could the document be scanned?", ("copy", "document", "may", "may")),
        ("mail", "may", "could the thesis be comb-bound?", ("heat", "document", "may", "may")),
        ("mail", "may", "could the draft be shredded?", ("heat", "document", "may", "may")),
    ],
)
def test_the_same_on_the_dataset_offices(
    office: str, requester: str, text: str, expected: tuple[str, ...]
) -> None:
    assert tasks_of(office, text, requester) == [expected]


@pytest.mark.parametrize(
    "text",
    [
        "has my report been bound yet?",  # its state, asked
        "is the binder working?",  # a facility's state
        "could it have been laminated?",  # a guess about the past, no "be"/"get" before it
        "could the report be ready by noon?",  # no service's participle
    ],
)
def test_a_question_about_state_moves_nothing(text: str) -> None:
    assert _repro(text).tasks == []


def test_a_colleague_after_the_modal_is_still_asked_about() -> None:
    # "could Ray be in tomorrow?": a person's whereabouts, no service (harbour's Ray)
    assert parser("harbour").parse("could Ray be in tomorrow?", "may").tasks == []
