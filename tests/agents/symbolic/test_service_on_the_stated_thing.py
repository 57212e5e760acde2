"""A service asked on "it" right after a statement about the speaker's own thing runs on that
thing: "the fob for my car's stopped working, can you get it reprogrammed", "my contract's got
coffee on it, could you photocopy it". Where the statement names several things, "it" is the
one the service asked takes as its input (``screen.service_input``); and a verb whose last
consonant English spells single or doubled ("reprogramed"/"reprogrammed", "labeled"/
"labelled") is asked for in either spelling (``core.language.verb_forms``). A request that
is no service ("bring it to Wang") after two things stated still asks which."""

from __future__ import annotations

import functools
from typing import Any

import pytest
from _offices import parser, tasks_of

from assistantx.agents.symbolic import InstructionParser
from assistantx.core import language
from assistantx.core.office import parse_office
from helpers.dataset_offices import HARBOUR_FILE
from helpers.yaml_files import raw_yaml


@functools.cache
def _key_desk() -> InstructionParser:
    """Harbour with car keys ("fob") and a key programmer in the badge office."""
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    raw["item_types"].append(
        {"id": "car_key", "name": "car key", "synonyms": ["fob", "key fob"], "kind": "personal"}
    )
    raw["operations"].append(
        {"id": "program", "name": "program", "verbs": ["program", "reprogram"], "input": "car_key"}
    )
    raw["facilities"].append(
        {
            "id": "key_programmer",
            "name": "key programmer",
            "location": "badge_office",
            "operations": ["program"],
            "guards": ["pat"],
        }
    )
    for p in raw["people"]:
        if p["id"] in ("may", "mark"):
            p["owns"].append({"type": "car_key", "known": True})
    return InstructionParser(parse_office(raw, "harbour with a key programmer"))


@pytest.mark.parametrize(
    "text",
    [
        "the fob for my car's stopped working, can you get it reprogrammed",
        "my fob's stopped working, can you get it reprogrammed",
        "the key fob for my van has died, can you get it reprogrammed please",
        "can you get my fob reprogrammed",
    ],
)
def test_the_service_runs_on_the_stated_key(text: str) -> None:
    frame = _key_desk().parse(text, "may")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("heat", "car_key", "may", "may")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "my document is all creased, can you get it copied?",
        "my contract's got coffee on it, could you photocopy it",
        "I spilt coffee on my contract, could you photocopy it",
    ],
)
def test_the_service_runs_on_the_stated_paper_default(text: str) -> None:
    assert tasks_of("default", text, "zhang") == [("copy", "document", "zhang", "zhang")]


def test_the_service_runs_on_the_stated_paper_harbour() -> None:
    text = "my timesheet's got tea on it, could you scan it"
    assert tasks_of("harbour", text, "may") == [("copy", "document", "may", "may")]


@pytest.mark.parametrize(
    "text",
    [
        "my contract's got coffee on it, could you bring it to Wang",
        "Lee has a stapler and Chen has scissors, bring it",
    ],
)
def test_no_service_after_two_things_still_asks(text: str) -> None:
    frame = parser("default").parse(text, "zhang")
    assert frame.tasks == [] and frame.question, frame


def test_both_spellings_of_a_doubled_consonant() -> None:
    assert {"programmed", "programed", "reprogramming"} <= set(
        language.verb_forms("program") | language.verb_forms("reprogram")
    )
    assert {"labelled", "labeled"} <= language.verb_forms("label")
    # one syllable always doubles, and a single spelling that is another word's is not added
    assert "scaned" not in language.verb_forms("scan")
    assert "taped" not in language.verb_forms("tap")
