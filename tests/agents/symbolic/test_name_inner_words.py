"""A word said only inside a longer name of a thing is no thing of the office on its own; at
the head of an imperative it is the verb, and a verb nothing here offers is declined (fixer
80c, class 2: in an office whose things are also called "heat pack" and "pocket book", "heat
up my lunch in the microwave pls" fetched the lunch unheated and "book us the lounge ..." was
no request; without those names both are declined) (``reading/name_inner_words.py``, used by
the screen's unsupported service). The whole name said ("bring me a heat pack", "pocket book
please") is still the thing, and where the office has a thing called by the word alone
("book" in the default office) nothing changes.

On a copy of Harbour (no heating, no booking, no washing) with hand warmers also called
"heat pack", a toiletry bag called "wash bag" and its notepad also called "pocket book"."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import HARBOUR_FILE, default_office, harbour_office
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml


@functools.cache
def _harbour_with_long_names() -> Office:
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    raw["item_types"] += [
        {
            "id": "hand_warmer",
            "name": "hand warmers",
            "synonyms": ["heat pack"],
            "kind": "personal",
        },
        {"id": "wash_bag", "name": "toiletry bag", "synonyms": ["wash bag"], "kind": "personal"},
    ]
    notepad = next(t for t in raw["item_types"] if t["id"] == "notepad")
    notepad["synonyms"].append("pocket book")
    rose = next(p for p in raw["people"] if p["id"] == "rose")
    rose["owns"] += [{"type": "hand_warmer", "known": True}, {"type": "wash_bag", "known": True}]
    return parse_office(raw)


_long = frame_reader(_harbour_with_long_names, "may")
_harbour = frame_reader(harbour_office, "may")
_default = frame_reader(default_office, "mao")

_DECLINES = [
    # the class's analogues
    ("heat up my lunch in the microwave pls", "heat"),
    ("book the lounge for 3pm for the team debrief", "book"),
    ("book us the lounge for 3pm for the team debrief", "book"),
    # variants: other verbs inside other names, other objects
    ("can you book lounge for 3pm", "book"),
    ("could you heat up my soup", "heat"),
    ("wash up my mug pls", "wash"),
]


@pytest.mark.parametrize(("text", "verb"), _DECLINES)
def test_a_word_only_inside_a_name_heads_as_an_unoffered_verb(text: str, verb: str) -> None:
    frame = _long(text)
    assert frame.tasks == [], frame
    assert (frame.decline or "").startswith(f"Sorry, I can't {verb}:"), frame


@pytest.mark.parametrize(("text", "verb"), _DECLINES)
def test_without_the_long_names_the_same_is_declined(text: str, verb: str) -> None:
    frame = _harbour(text)
    assert frame.tasks == [], frame
    assert (frame.decline or "").startswith(f"Sorry, I can't {verb}:"), frame


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        # the whole name said: the thing, never a verb
        ("bring me Rose's heat pack", "transfer", "hand_warmer"),
        ("can I have a pocket book", "produce", "notepad"),
        ("pocket book please", "produce", "notepad"),
        ("bring me Rose's wash bag", "transfer", "wash_bag"),
    ],
)
def test_the_whole_name_is_still_the_thing(text: str, kind: str, item: str) -> None:
    frame = _long(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [(kind, item)], frame


@pytest.mark.parametrize("text", ["heat pack for me please", "bring me a heat pack"])
def test_the_whole_name_at_the_head_is_asked_about_not_declined(text: str) -> None:
    """Only Rose has hand warmers: whose is asked, nothing declined."""
    frame = _long(text)
    assert frame.decline is None and frame.question == "Whose hand warmers do you mean?"


def test_a_thing_called_by_the_word_alone_keeps_it() -> None:
    """The default office has a "book": borrowing one is a fetch, booking a room declined."""
    assert [(t.kind, t.item) for t in _default("can I borrow Wang's book").tasks] == [
        ("transfer", "book")
    ]
    frame = _default("book the meeting room for 3pm")
    assert frame.tasks == [] and (frame.decline or "").startswith("Sorry, I can't book:")


def test_an_offered_verb_is_still_done() -> None:
    """The default office heats lunch: the same words ask for it."""
    frame = _default(
        "heat up my lunch in the microwave pls", "lee"
    )  # fix129e: a requester with lunch in the fridge (one with none is asked where it is)
    assert [(t.kind, t.item) for t in frame.tasks] == [("heat", "lunch")]
