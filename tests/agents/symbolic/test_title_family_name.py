"""A courtesy title goes with a family name: "Ms Grant" is Nadia Grant, even where "Grant" is
also another colleague's given name and an English word ("grant"); bare, "Grant" is the
colleague whose given name it is in an office written the English way (``given_name_meant``),
and still asked where family names come first. No gender is guessed ("Mr Grant" is the same
family name), and the office's own name order says which word is the family name
(``surnames.family_first``)."""

from __future__ import annotations

import copy
import functools
from pathlib import Path
from typing import Any

import pytest
import yaml

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE

# harbour (family names last): ray and ken renamed so "Grant" is one's family name and the
# other's given name; default (family names first, "Dr. Zhang"): "Mark" likewise
_RENAMED = {
    "harbour": {"ray": ("Nadia Grant", ["Nadia"]), "ken": ("Grant O'Sullivan", ["Grant"])},
    "default": {"xu": ("Mark Tian", ["Tian"]), "zheng": ("Jin Mark", ["Mark"])},
}


@functools.cache
def _parser(base: str) -> InstructionParser:
    source: Path = HARBOUR_FILE if base == "harbour" else DEFAULT_FILE
    raw: dict[str, Any] = copy.deepcopy(yaml.safe_load(source.read_text(encoding="utf-8")))
    for p in raw["people"]:
        if p["id"] in _RENAMED[base]:
            p["name"], p["aliases"] = _RENAMED[base][p["id"]][0], list(_RENAMED[base][p["id"]][1])
    office: Office = parse_office(raw, f"{base} with a family name that is a given name")
    return InstructionParser(office)


@pytest.mark.parametrize(
    ("base", "requester", "text", "doer"),
    [
        ("harbour", "mark", "could Ms Grant sign my form?", "ray"),
        ("harbour", "mark", "could Mr Grant sign my form?", "ray"),  # no gender guessed
        ("harbour", "mark", "can Dr Grant sign my document please", "ray"),
        ("default", "mao", "could Ms Mark sign my document?", "xu"),  # Mark Tian: family first
        ("default", "mao", "could Mr Mark stamp my document?", "xu"),
    ],
)
def test_a_title_goes_with_the_family_name(base: str, requester: str, text: str, doer: str) -> None:
    frame = _parser(base).parse(text, requester)
    assert frame.question is None, frame.question
    assert [t.actor for t in frame.tasks] == [doer]


def test_the_bare_name_is_the_given_name_in_english_order() -> None:
    # given name of Grant O'Sullivan, family name of Nadia Grant: his
    frame = _parser("harbour").parse("could Grant sign my form?", "mark")
    assert frame.question is None, frame.question
    assert [t.actor for t in frame.tasks] == ["ken"]


def test_the_bare_name_is_still_asked_with_family_names_first() -> None:
    frame = _parser("default").parse("could Mark sign my document?", "mao")
    assert not frame.tasks
    assert frame.question is not None and "Who do you mean" in frame.question


def test_the_word_without_a_title_is_no_person() -> None:
    # must not change: "the grant sign" is the word; nothing is asked of anyone
    frame = _parser("harbour").parse("the grant sign is broken", "mark")
    assert not frame.tasks
    assert frame.question is None


async def test_ms_grant_signs_in_the_simulated_office() -> None:
    from symbolic_run import run_instruction

    run = await run_instruction(_parser("harbour").office, "mark", "could Ms Grant sign my form?")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    asked = [r.action for r in run.stm.trace.actions() if r.action.type == "inquire"]
    assert [a.contact for a in asked] == ["ray"]  # type: ignore[attr-defined]
