"""Instruction understanding: the paraphrase set, clarifying questions and the round trip."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from symbolic_run import answer_first_question, expected_tasks, run_instruction

from assistantx.agents.symbolic import InstructionParser, Task
from assistantx.core.office import Office, parse_office
from assistantx.core.ports.messenger import ChatRef
from assistantx.sim.requester import NOTHING_TO_ADD
from helpers.yaml_files import raw_yaml

PARAPHRASES = Path(__file__).with_name("paraphrases.yaml")


PARAPHRASE_CASES: list[dict[str, Any]] = raw_yaml(PARAPHRASES)


def test_the_paraphrase_set_is_large() -> None:
    assert len(PARAPHRASE_CASES) >= 60


@pytest.mark.parametrize(
    "case",
    [pytest.param(c, id=f"{c.get('as', 'lee')}:{c['text']}") for c in PARAPHRASE_CASES],
)
def test_paraphrase_parses_to_its_frame_or_asks_or_declines(
    office: Office, case: dict[str, Any]
) -> None:
    frame = InstructionParser(office).parse(case["text"], case.get("as", "lee"))
    if case.get("clarify"):
        assert not frame.understood, f"acted on an unclear request: {frame.tasks}"
        assert frame.question
    elif case.get("decline"):
        assert not frame.understood, f"acted on a service the office lacks: {frame.tasks}"
        assert frame.question is None, f"asked instead of declining: {frame.question}"
        assert frame.decline is not None and "What I can do here:" in frame.decline
    else:
        assert frame.understood, f"asked instead: {frame.question}"
        assert frame.tasks == expected_tasks(case, case.get("as", "lee"))


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
    answer = answer_first_question(
        "lee", "lee", ChatRef(kind="dm", id="lee"), "oh sorry, I meant a stapler", answered
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


@pytest.mark.parametrize(
    ("text", "unclear"),
    [
        ("bring me the thing", "which item"),
        ("bring me Zhnag's stapler", "Zhang Wei or Zheng Hui"),
        ("please find me something for lunch", "which item"),
    ],
)
async def test_answer_that_says_nothing_gets_one_reask_then_a_failed_stop(
    office: Office, text: str, unclear: str
) -> None:
    # without a task's goal the simulated requester knows only what they wrote: they answer
    # that they have nothing to add (before, they answered as a colleague, "Yes, I'm here.
    # What do you need?", which no requester would say to "which item?")
    run = await run_instruction(office, "lee", text)
    trace = run.stm.trace
    asked = [r.action for r in trace.actions() if r.action.type == "inquire"]
    assert [a.contact for a in asked] == ["lee", "lee"]  # type: ignore[union-attr]
    assert asked[1].question.startswith("Sorry, I still don't understand.")  # type: ignore[union-attr]
    assert trace.outcome == "failed"
    last = run.sim.messenger.sent[-1]
    assert last.chat.id == "lee" and last.text.startswith("[failed]")
    assert repr(text) in last.text and unclear in last.text
    assert NOTHING_TO_ADD in last.text  # the answer that did not help is quoted
    assert not run.sim.world.handovers()


def test_time_phrases_and_purpose_clauses_are_not_objects(office: Office) -> None:
    parser = InstructionParser(office)
    book = [Task(kind="transfer", item="book", recipient="lee")]
    for text in (
        "find me a book to read over lunch",
        "after lunch, find me a book",
        "find me a book for lunch",
        "find me a book to read during my lunch",
    ):
        assert parser.parse(text, "lee").tasks == book, text
    # with no object before it, the same noun is the object
    assert parser.parse("heat up my lunch", "lee").tasks[0].item == "lunch"


def test_each_coordinated_object_gets_its_recipient(office: Office) -> None:
    frame = InstructionParser(office).parse("get me a stapler and a coffee for Wang", "lee")
    assert frame.tasks == [
        Task(kind="transfer", item="stapler", recipient="lee"),
        Task(kind="produce", item="coffee", recipient="wang"),
    ]
    frame = InstructionParser(office).parse("take my book and my pen to Wang", "lee")
    assert [t.recipient for t in frame.tasks] == ["wang", "wang"]


@pytest.mark.parametrize("text", ["heat my lunch and my book", "print my slides and my stapler"])
def test_an_object_no_task_covers_is_asked_about(office: Office, text: str) -> None:
    frame = InstructionParser(office).parse(text, "lee")
    assert not frame.understood
    assert frame.question is not None and "what you want me to do with the" in frame.question


@pytest.mark.parametrize(
    ("text", "item", "owner"),
    [
        ("take the stapler back to zhang", "stapler", "zhang"),
        ("give the book back to Wang Fang", "book", "wang"),
    ],
)
def test_returning_an_item_to_its_owner_takes_it_from_the_speaker(
    office: Office, text: str, item: str, owner: str
) -> None:
    # "back to X" makes X the owner, and the speaker the one who has it now (X lent it:
    # ``reading/given_back``): collected from the speaker and handed to X, never anyone's
    # stapler fetched for Zhang nor X asked about a thing the office's record puts with them
    frame = InstructionParser(office).parse(text, "lee")
    assert frame.tasks == [
        Task(kind="transfer", item=item, owner=owner, recipient=owner, source="lee")
    ]


def test_an_answer_naming_the_person_resolves_a_pronoun(office: Office) -> None:
    parser = InstructionParser(office)
    assert not parser.parse("bring me his stapler", "lee").understood
    frame = parser.parse_with_answers("bring me his stapler", "lee", ["Zhang Wei"])
    assert frame.tasks == [Task(kind="transfer", item="stapler", owner="zhang", recipient="lee")]


def test_an_answer_settles_an_ambiguous_name(office: Office) -> None:
    parser = InstructionParser(office)
    frame = parser.parse_with_answers("bring me Zhnag's stapler", "lee", ["Zheng Hui"])
    assert frame.tasks == [Task(kind="transfer", item="stapler", owner="zheng", recipient="lee")]
    # in the same sentence a second name is a role of its own, not an answer
    frame = parser.parse("take Zhnag's stapler to Zhang Wei", "lee")
    assert not frame.understood and "Zheng Hui" in (frame.question or "")
