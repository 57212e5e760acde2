"""A vague verb of work on a thing "with" a colleague ("can you sort out the contract thing with
Wang") asks what is to be done: the colleague is whom the matter is settled with, never the
thing's receiver (round 254's default-office sentence handed the document to Wang). A vague
verb with a receiver ("sort out a stapler for Wang") or with no colleague reads as before."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import answered_reader, frame_reader

_frame = frame_reader(load_office, "hu")
_answered = answered_reader(load_office, "hu")


@pytest.mark.parametrize(
    ("text", "thing", "person"),
    [
        ("can you sort out the contract thing with Wang", "document", "Wang Fang"),
        ("sort out my document with Zhang pls", "document", "Zhang Wei"),
        ("could you deal with the contract with Wang", "document", "Wang Fang"),
    ],
)
def test_what_to_do_with_a_colleague_is_asked(text: str, thing: str, person: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame
    assert frame.question is not None, frame
    assert frame.question.startswith(f"What should I do about the {thing} with {person}?"), frame


@pytest.mark.parametrize("answer", ["take it to her please", "just give my contract to Wang"])
def test_the_answer_says_what_to_do(answer: str) -> None:
    frame = _answered("can you sort out the contract thing with Wang", [answer])
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "document", "wang")
    ], frame


@pytest.mark.parametrize(
    ("text", "kind", "recipient"),
    [
        ("sort out a stapler for Wang", "transfer", "wang"),
        ("can you sort a coffee for me", "produce", "hu"),
    ],
)
def test_a_receiver_or_no_colleague_reads_as_before(text: str, kind: str, recipient: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.recipient) for t in frame.tasks] == [(kind, recipient)], frame


def test_an_answer_that_withdraws_does_nothing() -> None:
    frame = _answered("can you sort out the contract thing with Wang", ["never mind"])
    assert frame.tasks == [], frame
