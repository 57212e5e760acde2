"""A send-out asked with its purpose infinitive ("send my watch off to get repaired", "... to
be framed") names the work, never where it goes: "to get <participle>" after "send ... off"
was read as the destination, and the repair ran as a service done here and handed back, never
asking where (blind round 256: "send my shoes off to get resoled"). With no place said, the
send-out asks where, as "send my watch off for repair" does; a place said before the purpose
("off to Leeds to get repaired") is the destination, the purpose not part of it."""

from __future__ import annotations

import pytest
from _cafe_office import read_as_ana


@pytest.mark.parametrize(
    ("text", "asked"),
    [
        ("send my watch off to get repaired", "which repairer"),
        ("pls send my watch off to get repaired", "which repairer"),
        ("send my certificate off to get framed", "which framer"),
        # neighbours that asked already
        ("send my watch off to be repaired", "which repairer"),
        ("send my watch off for repair", "which repairer"),
    ],
)
def test_no_place_said_asks_where(text: str, asked: str) -> None:
    frame = read_as_ana(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert asked in frame.question


@pytest.mark.parametrize(
    "text",
    [
        "send my watch off to Leeds to get repaired",
        "send my watch off to Leeds to be repaired",
    ],
)
def test_the_place_before_the_purpose_is_the_destination(text: str) -> None:
    frame = read_as_ana(text)
    assert [(t.operation, t.item, t.destination) for t in frame.tasks] == [
        ("repair", "watch", "Leeds")
    ], frame
