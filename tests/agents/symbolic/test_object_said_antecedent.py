"""A work's verb, an article and words the office need not know ("print the press release")
say what a later "it"/"them" sent on to a colleague is: the product goes to them, as "print
the press release" alone is read, never asked which file "it" is; "print it and bring it
over", with nothing said, and a file brought to the speaker are still asked
(``reading.antecedent``). A lower-case given name after "to" is the colleague; "before the
2pm call" is when."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "mao")
_HARBOUR = frame_reader(harbour_office, "rose")


def _tasks(frame: object) -> list[tuple[str, str | None, str | None, str]]:
    return sorted((t.kind, t.item, t.owner, t.recipient) for t in getattr(frame, "tasks", []))


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("pls print the press release and take it to qiang before the 2pm call", "xu"),
        ("print the agenda and take them to jie", "chen"),
        ("could you print the seating plan and drop it with Zhang before lunch", "zhang"),
    ],
)
def test_the_said_object_is_what_it_refers_to(text: str, recipient: str) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [("print", "file", "mao", recipient)], frame


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("pls print the press release and take it to lindqvist before the 2pm call", "mark"),
        ("print the minutes and bring them to okafor", "may"),
    ],
)
def test_harbour_the_said_object_is_what_it_refers_to(text: str, recipient: str) -> None:
    frame = _HARBOUR(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [("print", "file", "rose", recipient)], frame


@pytest.mark.parametrize(
    "text",
    [
        "print it and bring it over",  # must not change: nothing said
        "print the minutes and bring them to me",  # must not change: brought to the speaker
    ],
)
def test_whose_file_is_still_asked(text: str) -> None:
    frame = _DEFAULT(text)
    assert frame.tasks == [], frame
    assert frame.question is not None and frame.question.startswith("Which file"), frame
