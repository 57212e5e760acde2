"""A possessive pronoun for a thing named before ("Inés and Thảo both sent retouches. print
hers and bring it to me", round 228's class, read after its final measure): "hers" is her
one, of whoever she is (asked when two are named); read as said, the speaker's own file was
printed. "is this pen hers?" says whose it is; "his" is left as said."""

from __future__ import annotations

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_mao = frame_reader(load_office, "mao")


def test_hers_of_two_named_asks_who() -> None:
    frame = _mao("Wang and Zhou both sent slides. print hers and bring it to me")
    assert frame.tasks == [] and frame.question is not None, frame
    assert "her" in frame.question


def test_hers_of_one_named_is_hers() -> None:
    frame = _mao("Zhou sent slides. print hers and bring it to me")
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [("print", "zhou", "mao")]


def test_theirs_of_whoever_lends_is_anyones() -> None:
    frame = _mao("my stapler is jammed, can someone lend me theirs")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", None, "mao")
    ], frame


def test_whose_it_is_is_no_object() -> None:
    frame = _mao("is this pen hers?")
    assert not any(t.owner for t in frame.tasks), frame
