"""A thing taken from a person's own place says whose it is (fixer fix62c; the testers'
sentences were never read): "Min needs paper for the printer, could you bring her some from my
desk", said by one who has paper, was read as anyone's paper, and the robot took a third
colleague's. "from my desk", "from my drawer", "from Chen's drawer": the person's own, where they
have one (``reading/keepers_place.py``); where they have none, as before. The default office:
Mao and Wu have paper, Lee, Chen and Hu pens, Zhang and Wang staplers; Mao has no pen."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.parser import InstructionParser
from helpers.dataset_offices import default_office

_PARSER = InstructionParser(default_office())


def _tasks(text: str, requester: str) -> list[tuple[str, str | None, str | None, str | None]]:
    frame = _PARSER.parse(text, requester)
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "requester", "expected"),
    [
        (
            "Min needs paper for the printer, could you bring her some from my desk",
            "wu",
            ("transfer", "paper", "wu", "gao"),
        ),
        (
            "could you bring Wang some paper from my desk",
            "mao",
            ("transfer", "paper", "mao", "wang"),
        ),
        ("take a pen from my drawer to Hu", "lee", ("transfer", "pen", "lee", "hu")),
        ("get Sun a pen out of my drawer please", "hu", ("transfer", "pen", "hu", "sun")),
    ],
)
def test_a_thing_from_a_persons_place_is_their_own(
    text: str, requester: str, expected: tuple[str, str, str, str]
) -> None:
    assert _tasks(text, requester) == [expected]


# -- must not change --------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("text", "requester", "expected"),
    [
        # Mao has no pen of his own: anyone's, as before
        ("bring me a pen from my desk", "mao", ("transfer", "pen", None, "mao")),
        ("take a pen from Chen's drawer to Hu", "lee", ("transfer", "pen", "chen", "hu")),
        ("grab me the stapler from Zhang's desk", "lee", ("transfer", "stapler", "zhang", "lee")),
        ("bring me paper", "mao", ("transfer", "paper", None, "mao")),
        ("bring me some paper from the printer", "mao", ("transfer", "paper", None, "mao")),
        ("bring the stapler to my desk", "wang", ("transfer", "stapler", None, "wang")),
        (
            "Wang's stapler is on my desk, bring it to me",
            "zhang",
            ("transfer", "stapler", "wang", "zhang"),
        ),
        ("take my pen from Chen's desk to Hu", "lee", ("transfer", "pen", "lee", "hu")),
    ],
)
def test_a_thing_not_taken_from_a_persons_place_is_as_before(
    text: str, requester: str, expected: tuple[str, str | None, str | None, str]
) -> None:
    assert _tasks(text, requester) == [expected]
