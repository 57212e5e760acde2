""" "any chance (that) <subject> could ..." asks for what follows as "could <subject> ..."
does, whoever the subject is: one asked ("any chance you could ..."), or the thing the work is
done on, said by a pronoun ("it", after the clause that names it) or by a noun phrase ("my
costume"). "go through the wash" is then the office's washing of the speaker's thing
(``reading.indirect_asks.chance_reworded``)."""

from __future__ import annotations

import pytest
from _offices import tasks_of

from helpers.kit_room import kit_room
from helpers.reading import frame_reader

_kit = frame_reader(kit_room, "ana")


@pytest.mark.parametrize(
    "text",
    [
        "my costume reeks of smoke, any chance it could go through the wash",
        "my costume is filthy. any chance that it could be washed?",
        "any chance my costume could go through the wash",
        "is there any chance my stage costume could be laundered",
        # must not change: said with "could" alone, or asked of the robot
        "my costume reeks of smoke, could it go through the wash",
        "any chance you could wash my costume",
    ],
)
def test_any_chance_a_thing_could_be_worked_asks_the_work(text: str) -> None:
    frame = _kit(text)
    assert [(t.item, t.owner, t.operation) for t in frame.tasks] == [("costume", "ana", "wash")], (
        frame
    )


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("my report is done, any chance it could be printed", [("print", "file", "lee", "lee")]),
        ("any chance my lunch could be heated", [("heat", "lunch", "lee", "lee")]),
        # must not change: the speaker asking for themself
        ("any chance I could have a pen", [("transfer", "pen", None, "lee")]),
    ],
)
def test_the_same_on_the_default_office(text: str, expected: list[object]) -> None:
    assert tasks_of("default", text, "lee") == expected
