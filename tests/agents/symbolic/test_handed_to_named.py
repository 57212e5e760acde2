"""A made product left with, for or on the desk of a named colleague goes to that colleague,
however the clause is set off ("photocopy my report, 2 copies, and leave them with Fang"):
"leave them ..." is a wish about people only where nobody is named as the one it is left
with (``reading.handed_to_named``)."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "mao")
_HARBOUR = frame_reader(harbour_office, "rose")


def _tasks(frame: object) -> list[tuple[str, str | None, str | None, str]]:
    return sorted((t.kind, t.item, t.owner, t.recipient) for t in getattr(frame, "tasks", []))


@pytest.mark.parametrize(
    ("text", "task"),
    [
        # the class's analogue: a given name alone ("Fang" is Wang Fang)
        ("photocopy my report, 2 copies, and leave them with Fang", ("copy", "document")),
        ("photocopy my report, two copies, and leave them with Fang", ("copy", "document")),
        ("photocopy my report, 3 copies please, and leave them for Fang", ("copy", "document")),
        ("photocopy my report, 2 copies, and leave them on Fang's desk", ("copy", "document")),
        ("photocopy my report, 2 copies, and drop them with Fang", ("copy", "document")),
        ("print my slides, 3 copies, and leave them with Wang", ("print", "file")),
    ],
)
def test_a_product_left_with_a_named_colleague_goes_to_them(
    text: str, task: tuple[str, str]
) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [(*task, "mao", "wang")], frame


@pytest.mark.parametrize(
    "text",
    [
        "print my report, 2 copies, and leave them with Lindqvist",
        "print my report, 3 copies, and leave them for Mark",
        "print my report, 2 copies, and leave them on Mark's desk",
    ],
)
def test_harbour_a_product_left_with_a_named_colleague_goes_to_them(text: str) -> None:
    frame = _HARBOUR(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [("print", "file", "rose", "mark")], frame


@pytest.mark.parametrize(
    "text",
    [
        "copy my report and leave it on my desk",  # must not change: the requester's
        "photocopy my report, 2 copies, and leave them on my desk",
        "photocopy my report, 2 copies, and leave them alone",  # a wish, nobody named
    ],
)
def test_no_colleague_named_keeps_the_product_with_the_requester(text: str) -> None:
    frame = _DEFAULT(text)
    assert _tasks(frame) == [("copy", "document", "mao", "mao")], frame


def test_keeping_people_away_is_still_a_wish() -> None:
    frame = _DEFAULT("leave them away from Fang")
    assert frame.tasks == [], frame
