"""Blind round 16, class 1: an operation lost after a clarifying question, then "Done".

On a small newsroom no sentence was written for (``helpers.newsroom``; the round's office
and sentences were never read): a page proof "needs a legal read" where a second operation
("style read") shares the head noun "read". Its whole display name names the operation, so
no "Who should get your page proof?" is asked (the proof comes back to the requester); a bare
"a read" asks which work is meant, never who gets it; an answer "Me." to a who-question never
turns the request into taking the proof from the requester and straight back; and a plan
that would do only that stops before it moves, saying so, instead of reporting done."""

from __future__ import annotations

import functools

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.agents.symbolic.evidence import gather
from assistantx.agents.symbolic.planning import Agenda, Planner
from assistantx.agents.symbolic.reading.parts import asked_part
from assistantx.agents.symbolic.roles import Roles
from assistantx.core.office import Office
from assistantx.core.task_schema import Task, TaskFrame
from assistantx.memory.graph import LongTermMemory
from helpers.consent_memory import memory
from helpers.newsroom import newsroom, newsroom_with_style_desk


@functools.cache
def _parser(office: Office) -> InstructionParser:
    return InstructionParser(office)


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.item, t.owner, t.recipient, t.operation) for t in frame.tasks]


@pytest.mark.parametrize("office", [newsroom(), newsroom_with_style_desk()])
@pytest.mark.parametrize(
    ("text", "operation"),
    [
        ("my court story proof needs a legal read before 6, can you sort it", "vet"),
        ("my proof could do with a quick legal read, can you sort it", "vet"),
        ("the council proof needs a proper legal read, can you get that done", "vet"),
        ("my proof needs a legal read", "vet"),
    ],
)
def test_the_whole_name_of_an_operation_asks_for_it(
    office: Office, text: str, operation: str
) -> None:
    frame = _parser(office).parse(text, "ines")
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(frame) == [("page_proof", "ines", "ines", operation)]


def test_each_of_two_names_sharing_a_head_noun_is_its_own_operation() -> None:
    frame = _parser(newsroom_with_style_desk()).parse(
        "my proof needs a style read, can you sort it", "ines"
    )
    assert _tasks(frame) == [("page_proof", "ines", "ines", "subedit")]


@pytest.mark.parametrize(
    "text",
    ["my proof needs a read, can you sort it", "my page proof wants a read before 6, sort it"],
)
def test_a_shared_head_noun_asks_which_work_not_who_gets_it(text: str) -> None:
    frame = _parser(newsroom_with_style_desk()).parse(text, "ines")
    assert frame.tasks == [] and frame.question is not None
    assert not frame.question.startswith("Who"), frame.question
    assert "legal read" in frame.question and "style read" in frame.question
    assert asked_part(frame.question) == "a read"


@pytest.mark.parametrize("answer", ["the legal read", "a legal read please", "legal read"])
def test_the_answer_naming_the_work_is_read_into_the_request(answer: str) -> None:
    frame = _parser(newsroom_with_style_desk()).parse_with_answers(
        "my proof needs a read, can you sort it", "ines", [answer]
    )
    assert _tasks(frame) == [("page_proof", "ines", "ines", "vet")]


@pytest.mark.parametrize("answers", [["Me."], ["Me.", "Me."], ["to me"]])
def test_me_never_turns_the_request_into_handing_the_proof_back(answers: list[str]) -> None:
    frame = _parser(newsroom_with_style_desk()).parse_with_answers(
        "my proof needs a read, can you sort it", "ines", answers
    )
    assert frame.tasks == [] and frame.question is not None


@pytest.mark.parametrize(
    "text",
    [
        "my proof had a legal read yesterday",
        "does my proof need a legal read?",
        "who does the legal read?",
        "my proof doesn't need a legal read",
        "thanks for the legal read on my proof!",
    ],
)
def test_the_name_outside_a_request_moves_nothing(text: str) -> None:
    frame = _parser(newsroom_with_style_desk()).parse(text, "ines")
    assert frame.tasks == [], (text, frame)


# -- the plan: taking an item from someone and straight back to them is no errand ----------


def _agenda(frame: TaskFrame) -> Agenda:
    office = newsroom()
    planner = Planner(office, Roles(office, office.distance))
    return planner.agenda(frame, LongTermMemory(office), gather(memory("ines", "x"), office), 0.0)


def test_a_plan_that_only_hands_the_item_back_stops_before_it_moves() -> None:
    """A frame from anywhere (an answer's re-reading, a hybrid's) that takes the requester's
    own proof from their desk and hands it straight back: nothing runs, and the reason says
    so, so the end reports it not done instead of "you now have your page proof"."""
    back = Task(kind="transfer", item="page_proof", owner="ines", recipient="ines")
    agenda = _agenda(TaskFrame(requester="ines", tasks=[back]))
    assert agenda.active is None
    assert [t.status for t in agenda.tasks] == ["unachievable"]
    assert "handed straight back" in (agenda.tasks[0].reason or "")


@pytest.mark.parametrize(
    "task",
    [
        Task(kind="transfer", item="page_proof", owner="ines", recipient="tomas"),
        Task(kind="transfer", item="lanyard", owner="marta", recipient="ines"),
        Task(kind="heat", item="page_proof", owner="ines", recipient="ines", operation="vet"),
        Task(kind="transfer", item="notebook", owner="cupboard", recipient="ines"),
    ],
)
def test_a_plan_that_moves_or_changes_something_runs(task: Task) -> None:
    agenda = _agenda(TaskFrame(requester="ines", tasks=[task]))
    assert [t.status for t in agenda.tasks] == ["active"]


async def test_the_legal_read_is_done_and_the_proof_comes_back() -> None:
    run = await run_instruction(
        newsroom_with_style_desk(),
        "ines",
        "my court story proof needs a legal read before 6, can you sort it",
    )
    questions = [r.action for r in run.stm.trace.actions() if r.action.type == "inquire"]
    assert not [q for q in questions if q.contact == "ines"]
    assert run.stm.trace.outcome == "done"
    assert "page_proof:ines" in run.sim.world.heated
    assert run.sim.world.holder["page_proof:ines"] == "ines"


async def test_the_keeper_is_asked_for_the_work_in_words_that_read() -> None:
    """ "legal read" opens with no verb: the keeper is asked by its declared verb ("could
    you vet ..."), never "could you legal read ..."; a name that opens with a verb reads as
    before."""
    run = await run_instruction(newsroom(), "ines", "my proof needs a legal read, can you sort it")
    [asked] = [
        r.action.question
        for r in run.stm.trace.actions()
        if r.action.type == "inquire" and r.action.contact == "oskar"
    ]
    assert "could you vet Ines Varga's page proof" in asked
    run = await run_instruction(
        newsroom_with_style_desk(), "ines", "my proof needs a style read, can you sort it"
    )
    [asked] = [
        r.action.question
        for r in run.stm.trace.actions()
        if r.action.type == "inquire" and r.action.contact == "femi"
    ]
    assert "could you style read Ines Varga's page proof" in asked
