"""A thing to have worked on, said after another request ("forward my file to Mark and have
my document digitised", "... and get my contract signed by Wang", "... and my report
printed"), is a request of its own: the work on that thing, the result back to the speaker
(blind round 63's class: the second piece of work was silently dropped). A second thing to
hand on ("... and my stapler too") is handed on as before."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office, load_office
from helpers.dataset_offices import DEFAULT_FILE, harbour_office
from helpers.reading import frame_reader


@functools.cache
def default_office() -> Office:
    return load_office(DEFAULT_FILE)


_harbour = frame_reader(harbour_office, "may")
_default = frame_reader(default_office, "chen")


@pytest.mark.parametrize(
    "text",
    [
        "Could you forward my file to Mark and have my document digitised?",
        "please send my file to Mark and get my document digitized",
        "forward my file to Mark, and have my document scanned please",
        "Could you forward my file to Mark and my document scanned?",
    ],
)
def test_the_work_said_after_a_forward_is_kept(text: str) -> None:
    frame = _harbour(text)
    assert frame.question is None and frame.decline is None, frame
    got = [(t.kind, t.item, t.recipient) for t in frame.tasks]
    assert got[0] == ("send_file", "file", "mark"), frame
    assert got[1:] == [("copy", "document", "may")], frame


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        ("send my report to Lee and get my contract signed by Wang", "sign", "document"),
        ("send my report to Lee and have my file printed", "print", "file"),
        ("bring my mug to Lee and my report printed", "print", "file"),
    ],
)
def test_the_work_said_after_a_delivery_is_kept(text: str, kind: str, item: str) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, frame
    assert len(frame.tasks) == 2, frame
    second = frame.tasks[1]
    assert (second.kind, second.item, second.recipient) == (kind, item, "chen"), frame


@pytest.mark.parametrize(
    ("text", "items"),
    [
        ("bring my mug to Lee and my stapler too", ["cup", "stapler"]),
        ("send my report to Lee and my mug too", ["document", "cup"]),
    ],
)
def test_a_second_thing_handed_on_is_handed_on(text: str, items: list[str]) -> None:
    frame = _default(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", i, "lee") for i in items
    ], frame
