"""What asks nothing and what does ask (round 186), on the default office as Lee and on
harbour as May:

* a mishap to the speaker's own thing told beside a request ("can anyone lend me a pen? I
  dropped mine down the back of the radiator") is why they ask
  (``taken_from_speaker.mishap_to_thing``), never news that it is had (the request was
  dropped); "drop it, never mind" and "... brought me one already" still withdraw;
* a laugh closing a remark about the speaker's own doing ("it'd be quicker if I just walked
  over to the print room myself haha") is no word of it (``speech_acts``): words, not "what
  do you need?"; a colleague named by an ordinary word ("Miles") is that word there;
* a wish about what a facility would do ("would be great if the coffee machine made hot
  chocolate some day", "if only the printer printed in colour") is words
  (``SpeechActs.world_wish``), never its service run nor a question about its input;
* a state told with a participle ("freezing in the meeting room") is no work asked of the
  room (``screen/wrong_instrument``): the request after it is read on its own;
* "is it possible to <verb> ..." asks for the verb like "would it be possible to"
  (``indirect_asks``), not about a facility's state; "is the fridge working?" still does."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.core.office import Office
from helpers.dataset_offices import DEFAULT_FILE, default_office, harbour_office
from helpers.reading import frame_reader
from helpers.renamed_offices import renamed

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "may")


@functools.cache
def _default_with_word_names() -> Office:
    """The default office, Dang Hao now Miles Dang and Mao Jun now Sunny Mao."""
    return renamed(
        DEFAULT_FILE,
        (("dang", "Miles Dang", ("Miles",)), ("mao", "Sunny Mao", ("Sunny",))),
        "default with a Miles and a Sunny",
    )


_named = frame_reader(_default_with_word_names, "lee")


def _tasks(frame: Any) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


def _understood(frame: Any) -> list[tuple[str, str | None, str | None, str | None]]:
    assert frame.question is None and frame.decline is None, frame
    return _tasks(frame)


def _words_only(frame: Any) -> None:
    """Nothing done, nothing asked back: acknowledged in words."""
    assert frame.tasks == [] and frame.question is None and frame.decline is not None, frame
    assert "dropped that request" not in frame.decline, frame


# --- class 1: a mishap to the speaker's own thing is why they ask ---


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("can anyone lend me a pen? I dropped mine down the back of the radiator", "pen"),
        ("could you find me some scissors? dropped mine and the blades bent", "scissors"),
        ("could you bring me a stapler? I dropped my stapler and it broke", "stapler"),
        ("bring me a pen, I dropped it down the sink", "pen"),
    ],
)
def test_default_mishap_to_own_thing_keeps_the_request(text: str, item: str) -> None:
    assert _understood(_default(text)) == [("transfer", item, None, "lee")]


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("can someone lend me a ruler? I dropped mine behind the filing cabinet", "ruler"),
        ("could you get me a calculator? dropped mine and the screen cracked", "calculator"),
    ],
)
def test_harbour_mishap_to_own_thing_keeps_the_request(text: str, item: str) -> None:
    assert _understood(_harbour(text)) == [("transfer", item, None, "may")]


@pytest.mark.parametrize(
    "text",
    [
        "bring me a pen, actually I dropped one off already",
        "bring me a pen, actually Wang already brought me one",
        "bring me a stapler. actually drop it, never mind",
    ],
)
def test_a_request_dropped_or_had_still_withdraws(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "dropped that request" in frame.decline, frame


# --- class 2: the speaker's own doing, with a closing laugh, asks nothing ---


@pytest.mark.parametrize(
    "text",
    [
        "it'd be way quicker if I just walked over to the print room myself haha",
        "it'd be easier if I fetched it myself haha",
        "I'll just grab it myself lol",
    ],
)
def test_default_own_doing_with_a_laugh_is_words(text: str) -> None:
    _words_only(_default(text))


def test_harbour_own_doing_with_a_laugh_is_words() -> None:
    _words_only(_harbour("it'd be easier if I just walked to the copy room myself lol"))


def test_a_name_that_is_a_word_inside_the_remark_is_the_word() -> None:
    _words_only(_named("it'd be miles quicker if I just walked over to the print room myself haha"))


def test_a_request_with_a_closing_laugh_is_unchanged() -> None:
    assert _understood(_default("bring me a stapler haha")) == [
        ("transfer", "stapler", None, "lee")
    ]


# --- class 3: a wish about what a facility would do is words ---


@pytest.mark.parametrize(
    "text",
    [
        "would be great if the coffee machine made hot chocolate some day",
        "would be handy if the printer printed in colour",
        "if only the printer printed in colour",
    ],
)
def test_default_wish_about_a_facility_is_words(text: str) -> None:
    _words_only(_default(text))


def test_harbour_wish_about_a_facility_is_words() -> None:
    _words_only(_harbour("if only the laminator laminated in colour"))


@pytest.mark.parametrize(
    "text",
    ["would be great if you could print my report", "if only the printer could print my file"],
)
def test_a_wish_that_asks_for_the_speakers_thing_is_still_a_request(text: str) -> None:
    assert [t[0] for t in _understood(_default(text))] == ["print"]


# --- class 4: a state told before the request leaves it standing ---


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("it's bright out but freezing in the meeting room, any chance of a coffee", "coffee"),
        ("freezing in the meeting room, could I get a coffee", "coffee"),
        ("boiling in the kitchenette, any chance of some water", "water"),
    ],
)
def test_default_state_then_request(text: str, item: str) -> None:
    assert _understood(_default(text)) == [("produce", item, None, "lee")]


def test_harbour_state_then_request() -> None:
    frame = _harbour("it's sunny out but freezing in the kitchen, could I get a tea")
    assert _understood(frame) == [("produce", "tea", None, "may")]


def test_a_colleague_named_sunny_makes_no_person_of_sunny_out() -> None:
    frame = _named("it's sunny out but freezing in the meeting room, any chance of a coffee")
    assert _understood(frame) == [("produce", "coffee", None, "lee")]


@pytest.mark.parametrize(
    "text", ["can you melt down the old mugs in the microwave?", "shred my stapler in the printer"]
)
def test_work_a_facility_does_not_do_is_still_declined(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "I can't" in frame.decline, frame


# --- class 5: "is it possible to <verb>" asks for the verb ---


@pytest.mark.parametrize(
    "text",
    [
        "is it possible to bring my lunch up from the fridge? stuck in a meeting",
        "is it possible to bring my lunch up from the fridge?",
    ],
)
def test_is_it_possible_to_bring_is_a_request(text: str) -> None:
    assert _understood(_default(text)) == [("transfer", "lunch", "lee", "lee")]


def test_is_it_possible_for_someone_to_get_is_a_request() -> None:
    frame = _default("is it possible for someone to bring me a coffee")
    assert _understood(frame) == [("produce", "coffee", None, "lee")]
    assert _understood(_harbour("is it possible to get a tea")) == [("produce", "tea", None, "may")]


def test_a_facilitys_state_is_still_asked() -> None:
    frame = _default("is the fridge working?")
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "in service" in frame.decline, frame
