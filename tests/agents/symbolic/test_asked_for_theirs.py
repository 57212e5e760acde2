"""Someone chased for their signature (``core.name_reading._asked_for_theirs`` and
``_asked_verb``): "chase mark for his signature on my document" asks Mark to sign the
speaker's document, which comes back to the speaker; "his"/"her" after "for"/"about" says the
name word before it is a person, even in lower case. Where a colleague is called Chase, "can
you chase frank ..." has "chase" where a request's verb goes, its object after it: the verb,
and "frank" the person. On harbour, the default office and a small office built here."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers import office_builder as ob
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader


def _raw_chase_office() -> dict[str, Any]:
    """Colleagues whose given names are English verbs and words (Chase, Frank, Bill)."""
    people = (
        ob.person("chase", "Chase Bell", "mug", aliases=["Chase"]),
        ob.person("frank", "Frank Osei", "stamp", aliases=["Frank"]),
        ob.person("bill", "Bill Hart", "mug", aliases=["Bill"]),
        ob.person("petra", "Petra Vlk", "mug"),
    )
    return ob.office_file(
        "chase office",
        people,
        rooms=[ob.room("post_room", "Post room", 4.0, 20.0)],
        item_types=[
            ob.item("permit", "permit", "personal", signable=True, synonyms=["licence"]),
            ob.item("stamp", "office stamp", seals=True),
            ob.item("mug", "mug"),
        ],
        operations=[],
        facilities=[],
        everyone_owns=["permit"],
        home="post_room",
    )


_chase_office = ob.parsed(_raw_chase_office)
_chase = frame_reader(_chase_office, "petra")
_harbour = frame_reader(harbour_office, "grace")
_default = frame_reader(default_office, "lee")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.actor, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "kind", "by"),
    [
        ("can you chase Mark for his signature on my document", "sign", "mark"),
        ("can you chase mark for his signature on my document", "sign", "mark"),
        ("could you nudge mark about his signature on my form", "sign", "mark"),
        ("hassle grace's colleague rose for her signature on my document", "sign", "rose"),
        ("bug will for his stamp on my contract pls", "seal", "will"),
    ],
)
def test_harbour_chased_for_their_work(text: str, kind: str, by: str) -> None:
    frame = _harbour(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _tasks(frame) == [(kind, "document", "grace", by, "grace")]


@pytest.mark.parametrize(
    ("text", "kind", "by"),
    [
        ("nudge Zhang for his seal on my contract", "seal", "zhang"),
        ("could you chase wang fang for her signature on my contract", "sign", "wang"),
    ],
)
def test_default_office_chased_for_their_work(text: str, kind: str, by: str) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _tasks(frame) == [(kind, "document", "lee", by, "lee")]


@pytest.mark.parametrize(
    ("text", "kind", "by"),
    [
        ("can you chase frank for his signature on my permit", "sign", "frank"),
        ("could you chase bill for his signature on my permit", "sign", "bill"),
        ("pls chase frank for his stamp on my permit", "seal", "frank"),
        ("chase bill about his signature on my licence", "sign", "bill"),
    ],
)
def test_a_colleague_called_chase_is_no_verbs_subject(text: str, kind: str, by: str) -> None:
    frame = _chase(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _tasks(frame) == [(kind, "permit", "petra", by, "petra")]


def test_chase_named_as_a_person_is_still_chase() -> None:
    """Neighbours: "to Chase", "Chase's mug" and "ask Chase to sign" keep Chase a person."""
    frame = _chase("can you take my permit to Chase")
    assert _tasks(frame) == [("transfer", "permit", "petra", None, "chase")]
    frame = _chase("ask Chase to sign my permit")
    assert _tasks(frame) == [("sign", "permit", "petra", "chase", "petra")]


def test_a_mark_given_for_something_is_no_person() -> None:
    """Neighbour: "a mark for her effort" (an article before it) stays the word: no one is
    asked for anything."""
    frame = _harbour("can you put a mark for her effort on my document")
    assert all(t.actor != "mark" and t.recipient != "mark" for t in frame.tasks)
