"""A colleague's given name said clipped, with a possessive (blind round 28's class, on an
office no sentence was written for, ``helpers.rota_desk``): "Rhi's ruler" is Rhiannon's,
where the office declares no such alias; "Alex's" clips both Alexandra and Alexei, so whom is
asked; a clip of nobody's name is still asked about."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.rota_desk import rota_desk

_frame = frame_reader(rota_desk, "ada")


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("Rhi's ruler, could you bring it to me", "rhiannon"),
        ("can I borrow Rhi's ruler", "rhiannon"),
        ("could you bring me Rhian's ruler", "rhiannon"),
        ("can I borrow rhi's ruler for a sec", "rhiannon"),
        ("could you fetch Alexa's ruler for me", "alexandra"),
    ],
)
def test_a_clipped_given_name_is_its_owner(text: str, owner: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "ruler", owner, "ada")
    ], frame


def test_a_clip_two_names_share_asks_whom() -> None:
    frame = _frame("can I borrow Alex's ruler")
    assert frame.tasks == []
    assert frame.question is not None
    assert "Alexandra Petrov" in frame.question and "Alexei Marr" in frame.question


@pytest.mark.parametrize("text", ["can I borrow Ad's ruler", "can I borrow Zed's ruler"])
def test_a_clip_of_nobody_is_asked_about(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None


def test_the_full_name_is_unchanged() -> None:
    frame = _frame("could you bring me Rhiannon's ruler")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("ruler", "rhiannon", "ada")]


def test_after_a_determiner_it_is_no_name() -> None:
    """ "my Rhi's ruler" reads no colleague: a given name never follows "my"."""
    frame = _frame("can I borrow my Rhi's ruler")
    assert all(t.owner != "rhiannon" for t in frame.tasks)
