"""A correction said with no pause before it ("i need a pen no wait a stapler", "a pen or
rather a stapler", "a pen sorry i mean a stapler", "a pen actually a stapler") replaces what
it corrects as the punctuated one does; a thing said by its purpose on either side ("something
to write with no wait something to cut with") is the office's item for that purpose
(``reading.screen.correction``)."""

from __future__ import annotations

import pytest
from _offices import tasks_of


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("i need something to write with no wait something to cut with", "scissors"),
        ("i need something to write with, no wait, something to cut with", "scissors"),
        ("i need something to cut with no wait something to write with", "pen"),
        ("bring me a pen no wait a stapler", "stapler"),
        ("bring me a pen sorry i mean a stapler", "stapler"),
        ("bring me a pen or rather a stapler", "stapler"),
        ("bring me a pen, or rather a stapler", "stapler"),
        ("bring me a pen actually a stapler", "stapler"),
        # must not change: the punctuated correction, a plain purpose
        ("bring me a pen, no wait, a stapler", "stapler"),
        ("i need something to write with", "pen"),
    ],
)
def test_the_later_thing_replaces_the_earlier(text: str, item: str) -> None:
    assert tasks_of("default", text, "lee") == [("transfer", item, None, "lee")]
