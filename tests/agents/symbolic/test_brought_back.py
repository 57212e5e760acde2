"""A second part said short and picked up on the way back is the speaker's
(``screen.brought_back``): "take my stapler to Zhang, and a coffee on the way back" makes the
coffee for the speaker, as "and on the way back get a coffee" does, never for Zhang. A short
part that says whom ("for Chen") or no way back ("and a coffee") is read as before. On the
default office and harbour."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "pat")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("office", "text", "tasks"),
    [
        (
            "default",
            "take my stapler to Zhang, and a coffee on the way back",
            [("transfer", "stapler", "zhang"), ("produce", "coffee", "lee")],
        ),
        (
            "default",
            "take my book to Chen and some water on your way back",
            [("transfer", "book", "chen"), ("produce", "water", "lee")],
        ),
        (
            "harbour",
            "take my ruler to Mark, and a tea on the way back",
            [("transfer", "ruler", "mark"), ("produce", "tea", "pat")],
        ),
        # neighbours: the part says whom, or no way back: read as before
        (
            "default",
            "bring my stapler to Zhang, and a coffee for Chen on the way back",
            [("transfer", "stapler", "zhang"), ("produce", "coffee", "chen")],
        ),
        (
            "default",
            "take my stapler to Zhang, and a coffee",
            [("transfer", "stapler", "zhang"), ("produce", "coffee", "zhang")],
        ),
    ],
)
def test_a_thing_picked_up_on_the_way_back(
    office: str, text: str, tasks: list[tuple[str, str, str]]
) -> None:
    frame = (_default if office == "default" else _harbour)(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _tasks(frame) == tasks
