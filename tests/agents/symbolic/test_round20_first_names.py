"""A word that is one colleague's first name and another's family name (blind rounds 20-22's
class, on ``helpers.galley``, an airline catering unit no sentence was written for: Cliff
Adebayo and Marcus Cliff). Colleagues are called by their first names: "cliff's running
order" is Cliff Adebayo's where he keeps one (also where both do, ``given_name_meant``);
never Marcus Cliff's without asking, even where only Marcus Cliff keeps a running order."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.agents.symbolic.reading.called_by import called_by, only_in_full_name
from assistantx.core.office import parse_office
from helpers.galley import galley, raw_galley
from helpers.reading import parser_for


@functools.cache
def _galley_where_only(keeper: str) -> InstructionParser:
    """The galley where only ``keeper`` keeps a running order."""
    raw: dict[str, Any] = raw_galley()
    for person in raw["people"]:
        owns = [o for o in person["owns"] if o["type"] != "running_order"]
        person["owns"] = owns + ([{"type": "running_order"}] if person["id"] == keeper else [])
    return InstructionParser(parse_office(raw, f"galley, {keeper} keeps the running order"))


_TEXTS = [
    "can you bring me cliff's running order",
    "can you bring me Cliff's running order",
    "Cliff has the running order, can you bring it to me",
]


@pytest.mark.parametrize("text", _TEXTS)
def test_only_marcus_cliff_keeps_one_and_it_is_asked(text: str) -> None:
    frame = _galley_where_only("marcus").parse(text, "nia")
    assert frame.tasks == [] and frame.question is not None
    assert "Cliff Adebayo" in frame.question and "Marcus Cliff" in frame.question


@pytest.mark.parametrize("text", _TEXTS)
def test_only_cliff_adebayo_keeps_one_and_it_is_his(text: str) -> None:
    frame = _galley_where_only("cliff").parse(text, "nia")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "running_order", "cliff", "nia")
    ]


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("can you bring me cliff's running order", "cliff"),
        ("can you bring me Marcus Cliff's running order", "marcus"),
        ("can you bring me marcus's running order", "marcus"),
    ],
)
def test_both_keep_one_and_the_given_name_says_whose(text: str, owner: str) -> None:
    frame = parser_for(galley).parse(text, "nia")
    assert frame.question is None, frame.question
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("running_order", owner, "nia")
    ]


def test_the_full_name_and_the_other_first_name_are_never_asked() -> None:
    p = _galley_where_only("marcus")
    for text in ("bring me Marcus Cliff's running order", "bring me marcus's running order"):
        frame = p.parse(text, "nia")
        assert [(t.owner, t.recipient) for t in frame.tasks] == [("marcus", "nia")], text


def test_who_is_called_what() -> None:
    office = galley()
    cliff, marcus, deepa = office.person("cliff"), office.person("marcus"), office.person("deepa")
    assert called_by(cliff, "cliff") and not called_by(marcus, "cliff")
    assert called_by(deepa, "dk") and called_by(marcus, "marcus")
    assert only_in_full_name(marcus, [cliff], "cliff")
    assert not only_in_full_name(cliff, [marcus], "cliff")
