"""A purpose's verb followed by a bare noun ("need to cut ribbon", "something to cut string
with") names what the tool works on: the noun is the purpose's object, never glued to the
tool's name. Blind round 212's default set: "I need to cut ribbon for the party banner" had
become "there is no scissors ribbon in this office"."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_frame = frame_reader(default_office, "gao")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I need to cut ribbon for the party banner. Anything sharp I could borrow?", "scissors"),
        ("I need to cut ribbon", "scissors"),
        ("I need something to cut string with", "scissors"),
        ("anything to cut cardboard with?", "scissors"),
        # as before: a determiner, a pronoun, the verb alone
        ("need to cut some string for the parcel, got anything?", "scissors"),
        ("I'm fixing a hem and have nothing to cut it with", "scissors"),
        ("I need something to write on", "paper"),
        ("I need something to write with", "pen"),
    ],
)
def test_the_tool_is_brought_for_the_speaker(text: str, item: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "gao")], (
        frame
    )
