"""bench/cascade_share.py judges a trace against a phrasing's expectation, case by case."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import pytest

from assistantx.core.office import Office, load_office

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))

import cascade_share


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


def case(outcome: str, **expect: Any) -> cascade_share.Case:
    return cascade_share.Case.model_validate(
        {
            "id": "c",
            "class": "k",
            "requester": "lee",
            "text": "t",
            "expect": {"outcome": outcome, **expect},
        }
    )


def trace(outcome: str, *actions: dict[str, Any]) -> dict[str, Any]:
    results = [{"action": a, "ok": True} for a in actions]
    return {"outcome": outcome, "steps": [{"results": results}]}


def collect(item: str, to: str) -> dict[str, Any]:
    return {"type": "send_qr", "contact": to, "item": item, "purpose": "collect"}


ASK_LEE = {"type": "inquire", "contact": "lee", "question": "which one?"}
STAPLER = {"deliver": [{"item": "stapler", "owner": "zhang", "to": "lee"}]}


def test_the_expected_delivery_to_the_right_person_is_right(office: Office) -> None:
    right, _ = cascade_share.judge(
        case("done", **STAPLER), trace("done", collect("stapler:zhang", "lee")), office
    )
    assert right


@pytest.mark.parametrize(
    ("actions", "why"),
    [
        ([collect("stapler:zhang", "wang")], "never handed to lee"),
        ([collect("stapler:wang", "lee")], "never handed to lee"),
        ([collect("stapler:zhang", "lee"), collect("pen:lee", "lee")], "also handed pen:lee"),
    ],
)
def test_a_wrong_or_extra_handover_is_wrong(
    office: Office, actions: list[dict[str, Any]], why: str
) -> None:
    right, reason = cascade_share.judge(case("done", **STAPLER), trace("done", *actions), office)
    assert not right and why in reason


def test_what_a_requested_service_takes_is_no_delivery(office: Office) -> None:
    printout = {"deliver": [{"item": "printout", "owner": None, "to": "lee"}]}
    handed = trace("done", collect("file:lee", "mao"), collect("printout:lee", "lee"))
    assert cascade_share.judge(case("done", **printout), handed, office)[0]


def test_nothing_physical_for_no_action_and_decline_and_ask_means_asking(office: Office) -> None:
    moved = trace("done", {"type": "move", "place": "desk_01"})
    assert not cascade_share.judge(case("no_action"), moved, office)[0]
    assert not cascade_share.judge(case("decline"), moved, office)[0]
    assert cascade_share.judge(case("decline"), trace("unachievable"), office)[0]
    assert not cascade_share.judge(case("ask"), trace("failed"), office)[0]
    assert cascade_share.judge(case("ask"), trace("failed", ASK_LEE), office)[0]


def test_consent_needs_a_question_to_each_person(office: Office) -> None:
    expect = case("done", consent=["zhang"], **STAPLER)
    handed = trace("done", collect("stapler:zhang", "lee"))
    right, reason = cascade_share.judge(expect, handed, office)
    assert not right and "Zhang" not in reason and "zhang" in reason


def test_a_bad_phrasings_file_is_one_line(tmp_path: Path) -> None:
    bad = tmp_path / "p.yaml"
    bad.write_text("cases:\n  - id: x\n    text: hi\n")
    with pytest.raises(SystemExit) as stopped:
        cascade_share.load_phrasings(bad)
    assert str(stopped.value).count("\n") == 0 and "cases.0" in str(stopped.value)
