"""A service's verb inside a thing's noun phrase, between a possessive or a determiner (with
nouns between) and a noun after it ("Ana's fitness *test* results file", "my *test* log file")
modifies that noun; it asks for no work (blind round 55's class; its office and sentences were
never read). The verb said as a verb still asks for the service."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.vet_yard import vet_yard

_frame = frame_reader(vet_yard, "gwen")


@pytest.mark.parametrize(
    "text",
    [
        "could you get Ana's fitness test results file for me?",
        "send me Ana's test results file",
        "could you get Ana's test results for me?",
    ],
)
def test_the_verb_in_a_noun_phrase_asks_no_service(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None or "test" not in frame.decline, frame
    assert all(t.operation is None for t in frame.tasks), frame
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("send_file", "file", "ana")], frame


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("test Ana's mask", "ana"),
        ("please test the mask", "gwen"),
        ("could you test my mask", "gwen"),
    ],
)
def test_the_verb_said_as_a_verb_asks_the_service(text: str, owner: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.operation) for t in frame.tasks] == [("mask", owner, "test")], frame


def test_print_my_file_still_prints() -> None:
    frame = _frame("print my file")
    assert [(t.kind, t.item) for t in frame.tasks] == [("print", "file")], frame


def test_a_service_on_the_wrong_thing_is_still_declined() -> None:
    frame = _frame("test my file")
    assert frame.decline is not None and "test" in frame.decline, frame
