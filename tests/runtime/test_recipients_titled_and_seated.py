"""The consent guard reads who was named as the reader does: a title goes with a family name
("Ms Grant" is Nadia Grant, not Grant O'Sullivan, whose given name it is), and a colleague
said to need a thing, with where they are said between ("Sue on reception needs a
highlighter"), is whom a "one" taken over goes to."""

from __future__ import annotations

import copy
from typing import Any

import pytest
import yaml

from assistantx.core.office import Office, parse_office
from assistantx.runtime.recipients import named_doers, named_recipients
from helpers.consent_memory import memory
from helpers.dataset_offices import HARBOUR_FILE, harbour_office


def _grants() -> Office:
    raw: dict[str, Any] = copy.deepcopy(yaml.safe_load(HARBOUR_FILE.read_text(encoding="utf-8")))
    names = {"ray": ("Nadia Grant", ["Nadia"]), "ken": ("Grant O'Sullivan", ["Grant"])}
    for p in raw["people"]:
        if p["id"] in names:
            p["name"], p["aliases"] = names[p["id"]][0], list(names[p["id"]][1])
    return parse_office(raw, "harbour with two Grants")


@pytest.mark.parametrize(
    ("text", "doer"),
    [
        ("could Ms Grant sign my form?", "ray"),
        ("could Mr Grant sign my form?", "ray"),
        ("could Grant O'Sullivan sign my form?", "ken"),  # the full name, as written
    ],
)
def test_a_title_goes_with_the_family_name(text: str, doer: str) -> None:
    office = _grants()
    doers = named_doers(office, memory("mark", text))
    assert doer in doers
    assert not ({"ray", "ken"} - {doer}) & doers


@pytest.mark.parametrize(
    ("requester", "text", "named"),
    [
        (
            "rose",
            "Sue on reception needs a highlighter, can you take one down from the cupboard",
            {"sue"},
        ),
        ("rose", "Sue needs a highlighter, can you take one over", {"sue"}),
        ("will", "Joy in the lounge needs a calculator, grab one from the cupboard", {"joy"}),
    ],
)
def test_one_taken_goes_to_the_one_said_to_need_it(
    requester: str, text: str, named: set[str]
) -> None:
    assert named_recipients(harbour_office(), memory(requester, text)) == named


@pytest.mark.parametrize(
    ("requester", "text"),
    [
        # must not change: "me" is whom it goes to; Sue is only said to need one
        ("rose", "Sue needs a highlighter, bring me one"),
        # two said to need: nobody is picked
        ("rose", "Sue needs a highlighter and Joy needs a highlighter, take one over"),
        # the possessive owns it, needs nothing
        ("rose", "Sue's highlighter is on reception, take one over"),
    ],
)
def test_nobody_else_is_named(requester: str, text: str) -> None:
    assert named_recipients(harbour_office(), memory(requester, text)) == set()
