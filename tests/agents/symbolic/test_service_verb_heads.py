"""An office's verb that is also a withdrawal word ("scrap") asks for the service when it names
the thing the service works on ("scrap my old tyre would you, it's worn through" was read as a
withdrawal: blind round 28's class); said of the request ("scrap that", "scrap it, never
mind") or of a thing the service never takes, it still withdraws and moves nothing."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.tyre_bay import tyre_bay

_frame = frame_reader(tyre_bay, "ines")


@pytest.mark.parametrize(
    "text",
    [
        "scrap my old tyre would you, it's worn through",
        "scrap my old tyre please",
        "scrap the tyre, it's bald",
    ],
)
def test_the_office_verb_on_its_thing_asks_for_the_service(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("heat", "tyre", "ines", "ines")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "scrap that",
        "scrap it, never mind",
        "bring me a ruler. scrap that",
        "bring me a ruler. actually scrap the ruler",
        "scrap my tyre. never mind",
    ],
)
def test_said_of_the_request_it_still_withdraws(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "dropped" in frame.decline
