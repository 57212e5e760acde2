"""What a thing already has is its state, never the speaker's having what was asked for
(fix93e class 4): "can my badge get laminated? it's already got coffee on it" was dropped as
withdrawn. "already got/have one" withdraws only when the speaker has it ("I've already got
one", and "got one already, thanks" with the subject dropped); "it's already got a stain on
it", "this one has already got a crease" describe the thing and the request stands."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_harbour = frame_reader(harbour_office, "rose")
_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "can my badge get laminated? it's already got coffee on it",
        "can my badge get laminated? this one has already got a crease",
        "can my badge get laminated? it has already got a tear in it",
    ],
)
def test_the_things_state_keeps_the_request_in_harbour(text: str) -> None:
    frame = _harbour(text)
    assert frame.decline is None, frame
    assert [(t.item, t.owner) for t in frame.tasks] == [("badge", "rose")]


def test_the_things_state_keeps_a_fetch_in_the_default_office() -> None:
    frame = _default("could you bring me a stapler? this one has already got a jam in it")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "stapler", "lee")]


@pytest.mark.parametrize(
    "text",
    [
        "can my badge get laminated? never mind, I've already got one",
        "can my badge get laminated? got one already, thanks",
    ],
)
def test_the_speaker_having_one_withdraws_in_harbour(text: str) -> None:
    frame = _harbour(text)
    assert frame.tasks == [] and frame.decline is not None, frame


@pytest.mark.parametrize(
    "text",
    [
        "could you bring me a stapler? got one already",
        "could you bring me a stapler? oh I've already got one",
    ],
)
def test_the_speaker_having_one_withdraws_in_the_default_office(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.decline is not None, frame


def test_a_question_opened_by_got_withdraws_nothing() -> None:
    frame = _default("could you bring me a stapler? got any in the cupboard?")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "stapler")]
