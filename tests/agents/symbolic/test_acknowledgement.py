"""An acknowledgement said back ("crystal clear, thanks!", "will do", "grand, cheers") asks for
nothing: answered in words, nothing done, no question, even in an office where a word of the
phrase is a colleague's name (Crystal, Grant for "grand", Sunny, Will). A request that names
one of them ("Crystal's ruler please") is still a request."""

from __future__ import annotations

import copy
import functools
from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import HARBOUR_FILE, default_office
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml

# harbour, with three colleagues named by words of acknowledgements (Will is harbour's own)
_RENAMED = {
    "ray": ("Crystal Reyes", ["Crystal"]),
    "dawn": ("Grant Sato", ["Grant"]),
    "ken": ("Sunny Abara", ["Sunny"]),
}


@functools.cache
def _named_office() -> Office:
    raw: dict[str, Any] = copy.deepcopy(raw_yaml(HARBOUR_FILE))
    for p in raw["people"]:
        if p["id"] in _RENAMED:
            p["name"], p["aliases"] = _RENAMED[p["id"]][0], list(_RENAMED[p["id"]][1])
    return parse_office(raw, "harbour with Crystal, Grant and Sunny")


_named = frame_reader(_named_office, "mark")
_default = frame_reader(default_office, "sun")


@pytest.mark.parametrize(
    "text",
    [
        "crystal clear, thanks!",
        "Crystal clear",
        "grand, cheers",
        "grand",
        "all sunny here, thanks",  # a remark on the day, "all" a degree word
        "will do",
        "will do, thanks",
        "will do thx mate",
        "sounds good",
        "fair enough, thanks",
        "got it, cheers",
        "all good",
        "no worries",
        "perfect",
        "that's perfect mate",
        "perfect, thanks Grant",
    ],
)
def test_an_acknowledgement_is_words_where_its_words_are_names(text: str) -> None:
    frame = _named(text)
    assert frame.tasks == [] and frame.question is None and frame.decline is not None, frame


@pytest.mark.parametrize(
    "text", ["will do, cheers Yang", "sounds good, thanks Wei", "no worries", "perfect"]
)
def test_an_acknowledgement_is_words_in_the_default_office(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.question is None and frame.decline is not None, frame


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("Crystal's ruler please", "ray"),
        ("sunny's ruler please", "ken"),
        ("perfect, bring me Sunny's ruler", "ken"),
        ("grand, can Grant bring me a ruler", "dawn"),
    ],
)
def test_a_request_naming_them_is_still_a_request(text: str, owner: str) -> None:
    frame = _named(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "ruler")], frame
    assert owner in (frame.tasks[0].owner, frame.tasks[0].actor), frame


def test_a_request_after_an_acknowledgement_is_done() -> None:
    frame = _default("great, can you bring me Wang's stapler")
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", "stapler", "wang")]


def test_an_acknowledgement_asked_back_is_no_acknowledgement() -> None:
    frame = _named("got it?")
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "Noted" not in frame.decline and "welcome" not in frame.decline, frame
