"""A verb that destroys only what it is said of ("rip up", "cut up", "tear up", "snap") on a
colleague's thing is declined in words: their thing is never fetched for it (the reader once
read "cut up X's contract" as a fetch of that contract). Said of the speaker's own thing, of
no one's, or a verb that destroys nothing ("tear off a sheet", "snap a photo") reads as before."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office, load_office
from helpers.dataset_offices import DEFAULT_FILE
from helpers.reading import frame_reader


@functools.cache
def _default() -> Office:
    return load_office(DEFAULT_FILE)


_frame = frame_reader(_default, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "cut up Sun Li's contract with the scissors, it's void anyway",
        "rip up Zhang's document",
        "could you tear up Wang's document please",
        "tear Wang's document up, it's out of date",
        "please rip Chen's printout in half",
        "snap Zhang's pen",
        "can you crush Wang's cup",
        "bin Zhang's document",
        "chuck Zhang's document in the bin",
        "throw Wang's printout in the bin",
        "get rid of Chen's book",
        "trash Zhang's document",
        "smash Wang's cup",
    ],
)
def test_destroying_a_colleagues_thing_is_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "people's things" in frame.decline, frame


@pytest.mark.parametrize(
    "text",
    [
        "cut up my old draft",
        "cut Lee a slice of cake",
        "tear off a sheet of Zhang's notepad for me",
        "snap a photo of Zhang's desk",
    ],
)
def test_no_colleagues_thing_destroyed_reads_as_before(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None or "people's things" not in frame.decline, frame


def test_a_plain_request_for_a_colleagues_thing_is_still_a_fetch() -> None:
    frame = _frame("bring me Zhang's document please")
    assert frame.decline is None, frame
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "zhang", "lee")
    ], frame
