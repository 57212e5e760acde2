"""A time inside a purpose said as a doing is the purpose's, not the need's
(``reading.future_need``): "I need scissors for wrapping presents tonight" wants the scissors
now, to have them by then, as "for the workshop tomorrow" does. A time said right after the
thing ("I need a stapler tomorrow") or a future form ("I'll need ...") still puts the need off
(answered in words, nothing fetched). On the dataset's default office and harbour."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_harbour = frame_reader(harbour_office, "pat")
_default = frame_reader(default_office, "lin")


def _read(office: str, text: str) -> TaskFrame:
    return (_harbour if office == "harbour" else _default)(text)


@pytest.mark.parametrize(
    ("office", "text", "item"),
    [
        # the class's analogues
        ("default", "I need a stapler for the workshop tomorrow", "stapler"),
        ("default", "I need scissors for wrapping presents tonight", "scissors"),
        # variants of our own: other doings, other times, other things, harbour
        ("default", "I need a stapler for putting up posters tomorrow", "stapler"),
        ("harbour", "I need a calculator for working out the budget on Friday", "calculator"),
        ("harbour", "I need a ruler for drawing the site plan later", "ruler"),
    ],
)
def test_a_time_in_a_doing_purpose_leaves_the_need_now(office: str, text: str, item: str) -> None:
    frame = _read(office, text)
    assert frame.decline is None, frame.decline
    assert [t.item for t in frame.tasks] == [item], frame.tasks


@pytest.mark.parametrize(
    ("office", "text"),
    [
        # must not change: the time right after the thing, or a future form, is the need's
        ("default", "I'll need a stapler tomorrow"),
        ("default", "I need scissors tomorrow for wrapping presents"),
        ("harbour", "I need a ruler tonight"),
    ],
)
def test_a_time_of_the_need_still_puts_it_off(office: str, text: str) -> None:
    frame = _read(office, text)
    assert frame.tasks == [], frame.tasks
    assert frame.decline is not None and frame.decline_outcome == "done", frame.decline
