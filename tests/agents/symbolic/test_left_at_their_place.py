"""A made thing, then "stick/pop/put/leave it on/in <colleague>'s <desk, console, tray...>"
("print off the new rota and stick it on Zhang's desk"): the printout is of the speaker's own
file (no owner said), delivered to that colleague; the possessive before the place is the
place's, never whose the printed thing is (fix59f class 2: the colleague's file was printed
and handed to the speaker). "Zhang's chart is done, print it" is still Zhang's, "the chart on
Zhang's desk" still lies there, "leave it on my desk" still goes to the speaker."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")
_as_zhang = frame_reader(load_office, "zhang")
_harbour = frame_reader(harbour_office, "may")


def _tasks(frame: object) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("print the agenda and pop it on Zhang's desk", ("print", "file", "lee", "zhang")),
        (
            "Print off the new rota and stick it on Zhang's desk please",
            ("print", "file", "lee", "zhang"),
        ),
        ("print the agenda and put it down on Wang's desk", ("print", "file", "lee", "wang")),
        ("print my slides and leave them on Zhang's desk", ("print", "file", "lee", "zhang")),
        ("copy my form and put it in Wang's tray", ("copy", "document", "lee", "wang")),
        # unchanged neighbours
        ("Zhang's chart is done, print it", ("print", "file", "zhang", "lee")),
        (
            "print the chart on Zhang's desk and bring it to me",
            ("print", "file", "zhang", "lee"),
        ),
        ("print the agenda and leave it on my desk", ("print", "file", "lee", "lee")),
        ("print my file and take it to Zhang", ("print", "file", "lee", "zhang")),
    ],
)
def test_the_place_is_whom_it_is_left_for(text: str, task: tuple[str, str, str, str]) -> None:
    frame = _frame(text)
    assert _tasks(frame) == [task], frame


def test_the_speakers_own_when_the_place_is_the_one_named() -> None:
    frame = _as_zhang("print off the agenda and pop it on Lee's desk")
    assert _tasks(frame) == [("print", "file", "zhang", "lee")], frame


@pytest.mark.parametrize("place", ["console", "bench"])
def test_a_console_is_a_persons_place(place: str) -> None:
    frame = _harbour(f"print off the new rota and stick it on Ray's {place} please")
    assert _tasks(frame) == [("print", "file", "may", "ray")], frame
