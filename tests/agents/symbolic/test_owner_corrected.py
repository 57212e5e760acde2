"""A correction of whose thing is meant (blind round 18's "not Wang's stapler, Zhang's - bring
it over please"): the new owner's thing takes the place of "it" in the request, and the new
owner is the one asked. Where no new owner is said, or the request names the item itself,
the correction is read as before."""

from __future__ import annotations

import pytest

from helpers.playschool import playschool
from helpers.reading import frame_reader

_frame = frame_reader(playschool, "ada")


@pytest.mark.parametrize(
    "text",
    [
        "not Rory's stapler, Miles's - bring it over please",
        "not rory's stapler, miles's one. can you bring it to me",
        "sorry not Rory's stapler, Miles's stapler - could you fetch it",
    ],
)
def test_the_corrected_owner_is_the_one_asked(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "miles", "ada")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "not Rory's stapler, Miles wants it - bring it over please",
        "not Rory's stapler, Rory's - bring it over please",
    ],
)
def test_no_new_owner_said_never_moves_the_old_owners_thing(text: str) -> None:
    frame = _frame(text)
    refused = {(h.person, h.value) for h in frame.hints if h.kind == "condition"}
    for t in frame.tasks:  # Rory's stapler, if read at all, stays marked as not wanted
        assert t.owner != "rory" or ("rory", "not wanted") in refused, frame
