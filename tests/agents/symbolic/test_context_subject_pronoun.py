"""A pronoun in a request after a context sentence about one named colleague ("Min's been
asking for crisps all afternoon. Could you get her a bag?") is that colleague (blind round
65's class: the context sentence was set aside as a mere fragment and "her" went to the
speaker). A request with no pronoun is still the speaker's; another colleague named in the
request is who gets it; a possessive before a fact still names whose thing "his" is."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office, load_office
from helpers.dataset_offices import DEFAULT_FILE
from helpers.reading import frame_reader


@functools.cache
def _office() -> Office:
    return load_office(DEFAULT_FILE)


_frame = frame_reader(_office, "mao")


@pytest.mark.parametrize(
    "text",
    [
        "Min's been asking for crisps all afternoon. Could you get her a bag from the "
        "vending machine?",
        "Min has been asking for crisps all afternoon. Could you get her a bag?",
        "Min asked for crisps earlier. grab her a bag please",
        "Min's been on about crisps since lunch. can you get her a packet",
    ],
)
def test_her_after_a_context_sentence_is_its_subject(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "snack", "gao")]


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("Min's been asking for crisps all afternoon. get me a bag", "mao"),
        ("Min's been asking for crisps all afternoon. get Lee a bag", "lee"),
        ("Min wants crisps. Could you get her a bag from the vending machine?", "gao"),
    ],
)
def test_near_misses_keep_their_reading(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("produce", "snack", recipient)
    ], frame


def test_a_possessive_before_a_fact_still_names_whose_his_is() -> None:
    frame = _frame("Lee's stapler is broken. bring me his document")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "document", "lee", "mao")
    ], frame
