"""A possessive written without its apostrophe (blind round 28's class, on an office no
sentence was written for, ``helpers.rota_desk``): "could u bring ottos ruler" is Otto's
ruler brought to the requester, Otto asked; on main the typo correction made "ottos" plain
"otto" and the ruler went to Otto. A plural that is an English word ("bills", "marks") is the
possessive only where the colleague it names keeps that item (Mark and Bill keep rulers;
Chase keeps none, so "chases ruler" may be Chase's or anyone's: the reader asks which,
``test_doubted_possessive_words``)."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.rota_desk import rota_desk

_frame = frame_reader(rota_desk, "ada")


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("could u bring ottos ruler", "otto"),
        ("could u bring me Ottos ruler", "otto"),
        ("can i borrow rhiannons ruler", "rhiannon"),
        ("pls fetch ottos steel rule for me", "otto"),
        ("could u bring marks ruler", "mark"),
        ("could u bring me bills ruler", "bill"),
    ],
)
def test_a_name_and_s_before_an_item_is_its_owner(text: str, owner: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "ruler", owner, "ada")
    ], frame


@pytest.mark.parametrize("text", ["could u bring chases ruler", "could u bring me chases ruler"])
def test_an_english_plural_is_not_taken_for_a_name_without_the_item(text: str) -> None:
    # Chase keeps no ruler: Chase's (which he lacks) or any ruler? Asked, never anyone's
    frame = _frame(text)
    assert frame.question is not None and ", or any ruler?" in frame.question, frame
    assert all(t.owner is None for t in frame.tasks), frame


@pytest.mark.parametrize(
    "text", ["take my ruler to otto", "take my ruler to ottos desk", "bring Otto my ruler"]
)
def test_a_name_before_no_item_still_receives(text: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("ruler", "ada", "otto")]
