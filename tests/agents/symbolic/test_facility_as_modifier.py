"""A facility's name between a possessive and a noun describes the thing owned: "print my
hydro session plan" (blind round 78: "hydro" is the pool's name) or "print my fridge rota" is
a print of the speaker's file, never "I can't help with the pool" nor a question about "my
hydro"; "take my fridge to Zhang" (the facility itself said as a belonging) is still asked
about."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_read = frame_reader(default_office, "wang")


@pytest.mark.parametrize(
    "text",
    [
        "print my fridge rota and bring it to me",
        "can you print my fridge rota",
    ],
)
def test_a_facility_word_before_a_noun_describes_the_file(text: str) -> None:
    frame = _read(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("print", "file", "wang")]


def test_the_facility_itself_said_as_a_belonging_is_still_asked_about() -> None:
    frame = _read("take my fridge to Zhang")
    assert frame.tasks == [] and frame.question is not None, frame.question
