"""A purpose's object said clipped, as people type in chat ("something to check the temps" of
a probe thermometer declared "to check temperatures"): the clipped word, or its plural, is
the start of the declared word, at least four letters and three short of it
(``screen.purpose_object``). The verb is never clipped; a clipping too short, or a word that
starts no declared word, finds nothing. On a small office (helpers.dive_van)."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.screen.purpose_object import said_as_declared
from helpers.dive_van import dive_van
from helpers.reading import frame_reader

_van = frame_reader(dive_van, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "need something to check the temps in the van b4 i load",
        "can I borrow something to check temps",
        "need something to measure volts on the van battery",
    ],
)
def test_a_clipped_object_finds_the_declared_purpose(text: str) -> None:
    frame = _van(text)
    assert frame.question is None and frame.decline is None, frame
    assert len(frame.tasks) == 1, frame
    assert frame.tasks[0].item in ("probe_thermometer", "multimeter"), frame
    assert frame.tasks[0].recipient == "lee", frame


@pytest.mark.parametrize(
    ("said", "declared", "same"),
    [
        ("check the temps", "check temperatures", True),
        ("check temp", "check temperatures", True),
        ("measure volts", "measure voltage", True),
        ("check the temperature", "check temperatures", True),  # must not change
        ("check tem", "check temperatures", False),  # too short to say which word
        ("chec temperatures", "check temperatures", False),  # the verb is never clipped
        ("check tamps", "check temperatures", False),  # no start of the word
        ("check temperatur", "check temperatures", False),  # a typo, not a clipping
    ],
)
def test_what_counts_as_a_clipping(said: str, declared: str, same: bool) -> None:
    assert said_as_declared(said, declared) is same
