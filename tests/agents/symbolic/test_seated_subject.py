"""A colleague described by their workstation as a need's subject (``reading.seated_subject``):
"the carver on bench 3 needs a set square. could you bring him mine" is Eoin's need (bench 3
is his place), met by one hand-over of the speaker's own set square to him; the need clause
alone never fetches a thing for the speaker. On a small office (helpers.dive_van) and the
default office."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.dataset_offices import default_office
from helpers.dive_van import dive_van
from helpers.reading import frame_reader

_van = frame_reader(dive_van, "lee")
_default = frame_reader(default_office, "lee")


def _moves(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "the carver on bench 3 needs a set square. could you bring him mine",
        "the carver on bench 3 needs a set square, can you take him mine",
        "the new lad at bench 3 needs a square. could you bring him mine please",
    ],
)
def test_him_is_the_one_at_the_place_and_mine_the_speakers(text: str) -> None:
    frame = _van(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _moves(frame) == [("transfer", "set_square", "lee", "eoin")], frame.explain()


@pytest.mark.parametrize(
    "text",
    [
        "the carver on bench 3 needs a set square",
        "the mason on bench 3 needs a square",
        "the guy at bench 3 wants a set square",
    ],
)
def test_the_need_alone_fetches_nothing_for_the_speaker(text: str) -> None:
    frame = _van(text)
    assert all(t.recipient != "lee" for t in frame.tasks), frame.explain()
    assert frame.question is not None and "Eoin Byrne" in frame.question, frame.question


def test_default_office_desk_said_for_its_colleague() -> None:
    frame = _default("the new guy at desk 4 needs a stapler, could you take him one")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("stapler", "zhang")]


@pytest.mark.parametrize(
    "text",
    [
        # must not change: a thing of the office at the place, and a bare description
        "the multimeter on bench 3 needs a set square",
        "Eoin needs a set square, could you bring him mine",
    ],
)
def test_things_and_names_are_read_as_before(text: str) -> None:
    frame = _van(text)
    assert all(t.recipient != "lee" for t in frame.tasks), frame.explain()


def test_the_consent_guard_reads_the_colleague_at_the_place_as_named() -> None:
    # the guard hands the set square to whom the requester named: the one at bench 3
    said = "the carver on bench 3 needs a set square. could you bring him mine"
    assert "eoin" in named_recipients(dive_van(), memory("lee", said))
    assert "eoin" not in named_recipients(dive_van(), memory("lee", "could you bring me mine"))
