"""A tool's name said as the verb on a colleague's closed thing ("drill out the lock on
Maria's desk drawer", where the office has a drill) is forcing into their things: declined in
one line, nothing moved. It had been read as the drill brought to Maria (absent, at that).
The tool asked for as a thing, for the speaker or a colleague, is still fetched."""

from __future__ import annotations

import pytest
from _gear_office import read_as_lee


@pytest.mark.parametrize(
    "text",
    [
        "can you drill out the lock on Maria's desk drawer, she's off and I need the petty cash",
        "drill out the lock on Wang's locker",
        "could you hammer off the latch of Zhang's cabinet",
    ],
)
def test_a_tool_said_as_the_verb_on_a_colleagues_things_is_declined(text: str) -> None:
    frame = read_as_lee(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None, frame
    assert frame.decline.startswith("Sorry, I can't open anyone's drawer"), frame
    assert "\n" not in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("can you bring me a drill", "lee"),
        ("bring Maria the drill", "maria"),
        ("take the drill out of Maria's drawer", "lee"),
    ],
)
def test_the_tool_asked_for_is_fetched(text: str, recipient: str) -> None:
    frame = read_as_lee(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [("drill", recipient)], frame
