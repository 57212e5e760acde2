"""Someone outside the office who wants a thing is not the speaker (reading/outsider_need.py,
reading/speaker_wants.py). "a friend of mine needs a ruler" fetched a ruler for the speaker
without a word: the double genitive ("a friend *of mine*", "a client *of ours*") hid the
outsider, and a want with a helping verb ("could do with", "would like") read as the
speaker's polite "could". Now the outsider's want is restated and asked ("Shall I bring a
ruler to you?"), a yes bringing it to the speaker to pass on. The speaker's own need "for"
an outsider ("I need a ruler for a friend") is a request of the speaker: it comes to them."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, answered_reader, frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")
_harbour_answered = answered_reader(harbour_office, "rose")


@pytest.mark.parametrize(
    ("read", "text", "question"),
    [
        (_harbour, "a friend of mine needs a ruler", "Shall I bring a ruler to you?"),
        (_harbour, "a friend of mine would like a ruler", "Shall I bring a ruler to you?"),
        (_harbour, "my daughter needs a calculator", "Shall I bring a calculator to you?"),
        (_default, "a client of ours could do with a pen", "Shall I bring a pen to you?"),
        (_default, "my daughter could use a pen", "Shall I bring a pen to you?"),
        (_default, "a visitor of mine wants a stapler", "Shall I bring a stapler to you?"),
    ],
)
def test_an_outsider_s_want_is_asked_never_delivered(
    read: ReadFrame, text: str, question: str
) -> None:
    frame = read(text)
    assert frame.tasks == [] and frame.question == question, frame


def test_a_yes_brings_it_to_the_speaker_to_pass_on() -> None:
    yes = _harbour_answered("a friend of mine needs a ruler", ("yes",))
    assert [(t.kind, t.item, t.recipient) for t in yes.tasks] == [("transfer", "ruler", "rose")]
    assert _harbour_answered("a friend of mine needs a ruler", ("no",)).tasks == []


@pytest.mark.parametrize(
    ("read", "text", "item", "who"),
    [
        # the speaker's own need, for someone outside: it comes to the speaker
        (_harbour, "I need a ruler for a friend", "ruler", "rose"),
        (_default, "I need a pen for my daughter", "pen", "lee"),
        (_default, "can I have a stapler for a visitor?", "stapler", "lee"),
        (_default, "I would like a coffee for my guest", "coffee", "lee"),
    ],
)
def test_the_speaker_s_own_need_for_an_outsider_comes_to_the_speaker(
    read: ReadFrame, text: str, item: str, who: str
) -> None:
    frame = read(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, who)], frame


@pytest.mark.parametrize(
    "text",
    [
        # handed to the outsider, or made for them with no speaker in need: asked as before
        "take a ruler to my friend",
        "we need a ruler for the man in reception, can you take it to him",
    ],
)
def test_a_thing_handed_to_an_outsider_is_still_asked_about(text: str) -> None:
    frame = _harbour(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Shall I bring it to you instead" in frame.question


def test_a_colleague_s_need_is_restated_as_before() -> None:
    assert _harbour("Mark needs a ruler").question == "Shall I bring a ruler to Mark Lindqvist?"
