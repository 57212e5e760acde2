"""Instruction understanding: the paraphrase set, clarifying questions and the round trip."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
import yaml
from symbolic_run import run_instruction

from assistantx.adapters.messenger.base import ChatRef
from assistantx.office import Office, parse_office
from assistantx.ppdr.events import TraceEvent
from assistantx.sim.office import SimOffice
from assistantx.symbolic import InstructionParser, Task

PARAPHRASES = Path(__file__).with_name("paraphrases.yaml")


def _expected(case: dict[str, Any]) -> list[Task]:
    requester = case.get("as", "lee")
    return [
        Task(
            kind=t["kind"],
            item=t.get("item"),
            owner=t.get("owner"),
            recipient=t.get("recipient", requester),
            actor=t.get("actor"),
        )
        for t in case["tasks"]
    ]


def test_paraphrases_parse_to_their_frames_or_ask(office: Office) -> None:
    cases = yaml.safe_load(PARAPHRASES.read_text(encoding="utf-8"))
    assert len(cases) >= 60
    parser = InstructionParser(office)
    right, asked, wrong = 0, [], []
    for case in cases:
        frame = parser.parse(case["text"], case.get("as", "lee"))
        if case.get("clarify"):
            ok = not frame.understood and bool(frame.question)
        else:
            ok = frame.understood and frame.tasks == _expected(case)
        if ok:
            right += 1
        elif not frame.understood:
            asked.append(case["text"])
        else:
            wrong.append((case["text"], frame.tasks))
    assert not wrong, f"acted on a wrong frame: {wrong}"
    assert right / len(cases) >= 0.95, f"only {right}/{len(cases)} right; asked for {asked}"


@pytest.mark.parametrize(
    "text",
    ["", "   ", "?!", "a" * 3000, "bring bring bring", "Smith's Smith's stapler", "ÄÖÜ ✓ 🙂"],
)
def test_odd_input_gives_a_question_not_an_error(office: Office, text: str) -> None:
    frame = InstructionParser(office).parse(text, "lee")
    assert not frame.understood and frame.question


def test_ambiguous_name_is_asked_about_never_guessed() -> None:
    office = parse_office(
        {
            "name": "tiny",
            "locations": [
                {"id": "d1", "kind": "workstation", "name": "D1", "x": 0, "y": 0},
                {"id": "d2", "kind": "workstation", "name": "D2", "x": 5, "y": 0},
                {"id": "d3", "kind": "workstation", "name": "D3", "x": 9, "y": 0},
            ],
            "item_types": [{"id": "mug", "name": "mug", "synonyms": ["cup"]}],
            "people": [
                {
                    "id": "ann",
                    "name": "Ann Park",
                    "location": "d1",
                    "handle": "@a",
                    "owns": [{"type": "mug"}],
                },
                {
                    "id": "bo",
                    "name": "Bo Park",
                    "location": "d2",
                    "handle": "@b",
                    "owns": [{"type": "mug"}],
                },
                {"id": "cy", "name": "Cy Lo", "location": "d3", "handle": "@c"},
            ],
            "facilities": [],
            "groups": [{"id": "all", "name": "All", "members": ["ann", "bo", "cy"]}],
            "robot": {"home": "d3"},
        }
    )
    parser = InstructionParser(office)
    frame = parser.parse("bring me Park's mug", "cy")
    assert not frame.understood and "Ann Park" in (frame.question or "")
    assert "Bo Park" in (frame.question or "")
    # another office's names and synonyms work without any change
    frame = parser.parse("could you get me Ann's cup?", "cy")
    assert frame.tasks == [Task(kind="transfer", item="mug", owner="ann", recipient="cy")]


def test_answer_completes_the_frame(office: Office) -> None:
    parser = InstructionParser(office)
    frame = parser.parse_with_answers("get my contract signed", "lee", ["Dr. Zhang please"])
    assert frame.tasks == [
        Task(kind="sign", item="document", owner="lee", recipient="lee", actor="zhang")
    ]
    # an answer that says nothing new leaves the question standing
    frame = parser.parse_with_answers("bring me the thing", "lee", ["Yes, I'm here."])
    assert not frame.understood


async def test_clarifying_round_trip_completes_the_task(office: Office) -> None:
    answered: list[str] = []

    async def answer(event: TraceEvent, sim: SimOffice) -> None:
        result = event.data.get("result")
        if event.kind != "action_result" or not isinstance(result, dict):
            return
        action = result["action"]
        if action["type"] == "inquire" and action["contact"] == "lee" and not answered:
            answered.append(action["question"])
            sim.messenger.post(
                "lee",
                ChatRef(kind="dm", id="lee"),
                "oh sorry, I meant a stapler",
                in_reply_to=result["data"]["question_id"],
            )

    run = await run_instruction(office, "lee", "Could you bring me something?", on_event=answer)
    assert answered and "?" in answered[0]
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"holds": ["lee", "stapler:*"]})
    first = run.stm.trace.steps[0].results
    assert [r.action.type for r in first] == ["inquire", "wait"]


async def test_unanswered_question_ends_without_acting(office: Office) -> None:
    run = await run_instruction(office, "lee", "hello there")
    trace = run.stm.trace
    assert trace.outcome == "failed"
    assert not run.sim.world.handovers()
    contacts = {r.action.contact for r in trace.actions() if r.action.type == "inquire"}  # type: ignore[union-attr]
    assert contacts == {"lee"}  # only the requester was asked; nobody else bothered
