"""A pronoun's contraction is two words, and a colleague's future clause is their own plan.

"give Will my letter, she'll frank it later" was declined "Sorry, I can't shell frank": the
apostrophe was folded away and "she'll" read as the word "shell". Kept apart ("she 'll"), and
with any clause "<he/she/they/Name> will <verb> ..." after a request read as what that
colleague will do themselves, only the hand-over is asked; before, "give Lee my document,
he'll copy it later" had the robot copy the document first (a wrong physical action)."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.contractions import contractions_apart
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "jack")
_harbour_mark = frame_reader(harbour_office, "mark")


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("give will my letter, she'll frank it later", "will"),
        ("give will my letter, she’ll frank it later", "will"),  # a curly apostrophe
        ("give will my letter, shell frank it later", "will"),  # typed without one
        ("take May my letter, she'll frank it tonight", "may"),
        ("take May my letter, he'll frank it tonight", "may"),
        ("take May my letter, they're going to frank it", "may"),
    ],
)
def test_a_colleagues_future_is_their_plan_on_harbour(text: str, recipient: str) -> None:
    frame = _harbour(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "document", recipient)
    ]


def test_a_colleagues_need_said_in_the_future_keeps_the_hand_over() -> None:
    frame = _harbour_mark("pass May my ruler, she'll need it tomorrow")
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "ruler", "may")]


@pytest.mark.parametrize(
    "text",
    [
        "give Lee my document, he'll copy it later",
        "give Lee my document, hell copy it later",
        "give Lee my document, Lee will copy it later",
        "give Lee my document, she's going to copy it later",
        "give Lee my document, they'll probably copy it later",
    ],
)
def test_a_colleagues_future_service_is_never_run_by_the_robot(text: str) -> None:
    frame = _default(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "document", "lee")]


def test_a_service_asked_before_the_hand_over_is_still_run() -> None:
    """Neighbour: "copy my document and give it to Lee" asks for the copy."""
    frame = _default("copy my document and give it to Lee")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("copy", "document", "lee")]


def test_the_speakers_own_future_asks_nothing() -> None:
    """Neighbour: "I'll frank it myself, thanks" is the speaker's own plan, no request."""
    frame = _harbour("I'll frank it myself, thanks")
    assert frame.tasks == []


def test_hell_as_a_word_is_left_as_said() -> None:
    """Neighbour: "what the hell" has a determiner before it; the request is read as before."""
    frame = _default("what the hell, give Lee my document")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("transfer", "lee")]


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("she'll frank it", "she 'll frank it"),
        ("He’ll frank it", "He 'll frank it"),
        ("ok, shell frank it", "ok, she 'll frank it"),
        ("we'll go", "we 'll go"),
        ("we're late", "we're late"),  # "were": read as folded by the rules for it
        ("they'll frank it", "they'll frank it"),  # "theyll" is no other word: as said
        ("the shell needs a polish", "the shell needs a polish"),
        ("hell yes", "hell yes"),
        ("shell out for it", "shell out for it"),
    ],
)
def test_contractions_kept_apart(text: str, said: str) -> None:
    assert contractions_apart(text)[0] == said
