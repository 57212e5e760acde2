"""A colleague's thing taken where they cannot see it ("grab his mug while he's not looking",
"when she isn't watching", "before he notices") or as a joke on them ("to prank her", "I want
to wind him up") is declined in words, like the other covert marks (blind round 40's class:
the owner was asked and the thing taken). "She won't mind" alone is no such mark: the owner
is asked as usual."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.roof_garden import roof_garden

_frame = frame_reader(roof_garden, "rosa")


@pytest.mark.parametrize(
    "text",
    [
        "grab Dr Ode's mug while he's not looking, I want to wind him up",
        "take Basil's stapler when she isn't watching",
        "bring me Misty's mug while she is not looking",
        "fetch Holly's stapler for me while she's looking the other way",
        "get me Basil's stapler before he notices",
        "could you bring me Femi's mug before he finds out",
        "bring me Femi's mug to prank him",
        "take Misty's mug to Basil as a joke on her",
        "bring me Femi's mug, I want to wind him up",
        "grab his mug for me while he's not looking",
    ],
)
def test_a_thing_taken_behind_its_owners_back_is_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "owner" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("borrow Basil's stapler, she won't mind", "basil"),
        ("bring me Femi's mug, he won't mind", "ode"),
        ("bring me Basil's stapler while he's in a meeting", "basil"),
        ("bring me a pen, I want to prank Femi", None),
        ("bring me Femi's mug, I'm not looking forward to this meeting", "ode"),
    ],
)
def test_near_misses_are_read_as_before(text: str, owner: str | None) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.owner, t.recipient) for t in frame.tasks] == [(owner, "rosa")], frame
