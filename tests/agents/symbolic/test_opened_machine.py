"""A machine opened to take a thing out ("open the microwave and take my lunch out") asks
for the taking out, read as "take my lunch out of the microwave" is: the machine's service is
never run (the lunch was heated again before it was handed over). Said while the machine is
still at work it is declined as before (``running_machine``); "open the door and take my
lunch out" names no machine and reads as before."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.parser import InstructionParser
from assistantx.agents.symbolic.reading.screen.opened_machine import opened_to_take
from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "zhang")  # Zhang Wei has a lunch


@pytest.mark.parametrize(
    "text",
    [
        "open the microwave and take my lunch out",
        "can you open the microwave and get my lunch out pls",
    ],
)
def test_only_taken_out(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "lunch", "zhang", "zhang")
    ], frame


def test_still_at_work_is_declined() -> None:
    frame = _frame("open the microwave and take my lunch out, I know it's still going")
    assert not frame.tasks and frame.decline is not None, frame
    assert "still at work" in frame.decline


def test_heating_asked_is_still_heating() -> None:
    frame = _frame("heat my lunch in the microwave")
    assert [t.kind for t in frame.tasks] == ["heat"], frame


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("open the microwave and take my lunch out", "take my lunch out of the microwave"),
        ("open the door and take my lunch out", "open the door and take my lunch out"),
        ("open the microwave and wait", "open the microwave and wait"),
    ],
)
def test_opened_to_take(text: str, said: str) -> None:
    terms = InstructionParser(load_office()).screen.terms
    assert opened_to_take(terms, text)[0] == said
