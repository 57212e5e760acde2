"""An elided possessive ("can you get me Wu's?") means the thing named last before it, and a
thing's word said bare after a preposition of time or going ("took the pen *to lunch*",
"*at lunch*") names an occasion, not that thing (``screen.elided_possessive.things_named``).
On main "Hu took the pen to lunch, can you get me Wu's?" fetched Wu's lunch. Neighbours: a
lunch that is the thing ("Zhang ate his lunch, can you get me Wu's?") and a possessive with
its noun ("can you get me Zhang's stapler") read as before."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lin")
_harbour = frame_reader(harbour_office, "may")


def _tasks(frame: TaskFrame) -> list[tuple[str | None, str | None, str]]:
    return [(t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # Wu keeps a pen and a lunch: the pen is meant
        ("Hu took the pen to lunch, can you get me Wu's?", ("pen", "wu", "lin")),
        ("Chen's at lunch with the pen, could you grab me Wu's?", ("pen", "wu", "lin")),
        ("Wang took the stapler to lunch, can you get me Hu's?", ("stapler", "hu", "lin")),
        ("Zhang ate his lunch, can you get me Wu's?", ("lunch", "wu", "lin")),  # neighbour
        ("can you get me Zhang's stapler", ("stapler", "zhang", "lin")),  # neighbour
    ],
)
def test_default_the_thing_not_the_occasion(text: str, expected: tuple[str, str, str]) -> None:
    assert _tasks(_default(text)) == [expected]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # Grace keeps a ruler and a lunch: the ruler is meant
        ("Joy took the ruler to lunch, can you grab Grace's?", ("ruler", "grace", "may")),
        ("Ken went to lunch with the ruler, can you get me Art's?", ("ruler", "art", "may")),
        ("can you get me Will's lunch", ("lunch", "will", "may")),  # neighbour
    ],
)
def test_harbour_the_thing_not_the_occasion(text: str, expected: tuple[str, str, str]) -> None:
    assert _tasks(_harbour(text)) == [expected]
