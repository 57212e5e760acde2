"""A name joined by "and" to a possessive name ("Wang and Sun's files") owns such a thing too:
the errand is done on each owner's thing, and the first name is no recipient
(``reading.joined_owners``)."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "lee")
_HARBOUR = frame_reader(harbour_office, "will")


def _tasks(frame: object) -> list[tuple[str, str | None, str | None, str]]:
    tasks = getattr(frame, "tasks", [])
    return sorted((t.kind, t.item, t.owner, t.recipient) for t in tasks)


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "bring Wang and Sun's files to me",
            [("send_file", "file", "sun", "lee"), ("send_file", "file", "wang", "lee")],
        ),
        (
            "email me Wang and Sun's files",
            [("send_file", "file", "sun", "lee"), ("send_file", "file", "wang", "lee")],
        ),
        (
            "take Wang and Sun's staplers to Mao",
            [("transfer", "stapler", "sun", "mao"), ("transfer", "stapler", "wang", "mao")],
        ),
    ],
)
def test_default_each_owners_thing(text: str, tasks: list[tuple[str, str, str, str]]) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == sorted(tasks), frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "print Rose and Mark's files for me",
            [("print", "file", "mark", "will"), ("print", "file", "rose", "will")],
        ),
        (
            "bring me Pat and Mark's rulers",
            [("transfer", "ruler", "mark", "will"), ("transfer", "ruler", "pat", "will")],
        ),
    ],
)
def test_harbour_each_owners_thing(text: str, tasks: list[tuple[str, str, str, str]]) -> None:
    frame = _HARBOUR(text)
    assert frame.question is None, frame
    assert _tasks(frame) == sorted(tasks), frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # neighbours: a recipient, then someone else's thing (no "and" between the names)
        ("bring Wang Sun's file", [("send_file", "file", "sun", "wang")]),
        (
            "give Wang my stapler and Sun's file",
            [("send_file", "file", "sun", "wang"), ("transfer", "stapler", "lee", "wang")],
        ),
    ],
)
def test_no_joined_owner_is_unchanged(text: str, tasks: list[tuple[str, str, str, str]]) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == sorted(tasks), frame
