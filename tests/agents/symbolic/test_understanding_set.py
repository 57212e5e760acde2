"""The understanding set of issue 16: instructions across both offices, case by case.

Each case names its office, requester and text and what it must become: the exact frame,
a decline (with its outcome), or a question. There is no threshold: every case passes.
"""

from __future__ import annotations

import functools
from pathlib import Path
from typing import Any

import pytest
import yaml
from symbolic_run import expected_tasks

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import load_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE

OFFICES = {"default": DEFAULT_FILE, "harbour": HARBOUR_FILE}
CASES: list[dict[str, Any]] = yaml.safe_load(
    Path(__file__).with_name("understanding_set.yaml").read_text(encoding="utf-8")
)


@functools.cache
def _parser(office: str) -> InstructionParser:
    return InstructionParser(load_office(OFFICES[office]))


def test_the_set_is_large_and_covers_both_offices() -> None:
    assert len(CASES) >= 120
    assert {c["office"] for c in CASES} == set(OFFICES)
    assert sum(c["office"] == "harbour" for c in CASES) >= 40


@pytest.mark.parametrize("case", CASES, ids=[f"{c['office']}:{c['text']}" for c in CASES])
def test_case(case: dict[str, Any]) -> None:
    requester = case["as"]
    frame = _parser(case["office"]).parse(case["text"], requester)
    if "tasks" in case:
        assert frame.understood, frame.question or frame.decline
        assert frame.tasks == expected_tasks(case, requester)
    elif "decline" in case:
        assert frame.tasks == [] and frame.decline, frame.question
        assert frame.decline_outcome == case["decline"]
    else:
        assert case.get("ask") is True
        assert frame.tasks == [] and frame.decline is None
        assert frame.question and frame.question.count("?") >= 1
    hints = [f"{h.kind}:{h.person}:{h.value}" for h in frame.hints]
    assert hints == case.get("hints", [])
