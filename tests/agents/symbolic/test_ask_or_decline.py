"""Ask or decline, never guess: the understanding contract of issue 16, case by case.

Each clause of the contract has its cases at the parser (the frame) and, for the ones that
end in the physical world, a run in the simulated office checking what was handed to whom.
"""

from __future__ import annotations

from typing import Any

import pytest
from symbolic_run import answer_first_question, run_instruction

from assistantx.agents.symbolic import InstructionParser, Task
from assistantx.core.office import Office, parse_office
from assistantx.core.ports.messenger import ChatRef


@pytest.fixture(scope="module")
def parser(office: Office) -> InstructionParser:
    return InstructionParser(office)


def _handed(run: Any) -> list[tuple[str, str]]:
    """(item, to whom) of every item that left the locker to a person."""
    return [
        (e.detail["item"], e.detail["to"])
        for e in run.sim.world.handovers()
        if e.detail.get("to") not in (None, "locker")
    ]


# -- a negated or withdrawn request does nothing and says so ----------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "don't bring me a stapler",
        "please do not print my file",
        "I don't need a stapler anymore",
        "no need to make me a coffee",
        "Don't send my slides to Zhou Yan.",
        "never mind",
        "bring me a stapler. actually, forget it",
        "Get me a coffee. Cancel that.",
    ],
)
def test_negated_or_withdrawn_request_is_declined_as_nothing_to_do(
    parser: InstructionParser, text: str
) -> None:
    frame = parser.parse(text, "lee")
    assert frame.tasks == [] and frame.question is None
    assert frame.decline is not None and "nothing" in frame.decline
    assert frame.decline_outcome == "done"


def test_a_later_request_after_withdrawing_is_the_request(parser: InstructionParser) -> None:
    frame = parser.parse("bring me a stapler. never mind, bring me a pen instead", "wang")
    assert frame.tasks == [Task(kind="transfer", item="pen", recipient="wang")]


def test_a_negation_that_is_not_the_request_verb_keeps_the_request(
    parser: InstructionParser,
) -> None:
    frame = parser.parse("I don't have a stapler, can you bring me one", "lee")
    assert frame.tasks == [Task(kind="transfer", item="stapler", recipient="lee")]


async def test_negated_request_runs_to_a_stop_without_acting(office: Office) -> None:
    run = await run_instruction(office, "lee", "please don't bring me a stapler")
    assert run.stm.trace.outcome == "done"
    assert run.actions == ["stop"]
    assert not run.sim.world.handovers()
    told = run.sim.messenger.sent[-1]
    assert told.chat.id == "lee" and "did nothing" in told.text


# -- an operation the office does not offer is declined, naming what it can do ----------------
@pytest.mark.parametrize(
    ("text", "word"),
    [
        ("scan my contract", "scan"),
        ("Could you scan my contract and email it to me?", "scan"),
        ("make me a cup of tea", "tea"),
        ("can you get me a cup of tea please", "tea"),
        ("book me a taxi", "book"),
        ("fax my contract to Zhang", "fax"),
        ("please laminate my form", "laminate"),
        ("order me a pizza", "pizza"),
    ],
)
def test_unoffered_service_is_declined_never_swapped(
    parser: InstructionParser, text: str, word: str
) -> None:
    frame = parser.parse(text, "lee")
    assert frame.tasks == [] and frame.decline is not None
    assert frame.decline_outcome == "unachievable"
    assert word in frame.decline
    assert "printer" in frame.decline and "coffee machine" in frame.decline  # what it can do


@pytest.mark.parametrize(
    "text",
    [
        "Grab me some wet wipes, I spilled my tea",
        "I spilled my tea. Please get me some wet wipes.",
        "get me some wipes for my tea",
    ],
)
def test_a_service_word_outside_the_request_is_only_context(
    parser: InstructionParser, text: str
) -> None:
    assert parser.parse(text, "lee").tasks == [Task(kind="transfer", item="wipes", recipient="lee")]


async def test_unoffered_service_runs_to_unachievable_without_acting(office: Office) -> None:
    run = await run_instruction(office, "wang", "Please scan my contract")
    assert run.stm.trace.outcome == "unachievable"
    assert run.actions == ["stop"]
    assert not run.sim.world.handovers()
    assert "printer" in run.sim.messenger.sent[-1].text


# -- destructive or harmful requests are declined ----------------------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "throw away Wang's stapler",
        "please get rid of my old book",
        "can you bin Zhang's contract",
        "Hide Zhang's stapler, it's a prank",
        "take Wang's stapler and throw it away",
        "could you destroy my document",
    ],
)
def test_destructive_request_is_declined(parser: InstructionParser, text: str) -> None:
    frame = parser.parse(text, "lee")
    assert frame.tasks == [] and frame.decline is not None
    assert frame.decline_outcome == "unachievable" and "won't" in frame.decline


async def test_destructive_request_fetches_nothing(office: Office) -> None:
    run = await run_instruction(office, "lee", "throw away Wang's stapler")
    assert run.stm.trace.outcome == "unachievable"
    assert run.actions == ["stop"] and not run.sim.world.handovers()


# -- statements of fact become hints and never make a party ------------------------------------
@pytest.mark.parametrize(
    ("text", "tasks", "hint"),
    [
        (
            "bring me a stapler? Wang is away",
            [Task(kind="transfer", item="stapler", recipient="lee")],
            ("availability", "wang", "away"),
        ),
        (
            "Can you get me Hu's stapler? Wang is away",
            [Task(kind="transfer", item="stapler", owner="hu", recipient="lee")],
            ("availability", "wang", "away"),
        ),
        (
            "Wang's away, so get me a stapler",
            [Task(kind="transfer", item="stapler", recipient="lee")],
            ("availability", "wang", "away"),
        ),
        (
            "Bring me a stapler. Zhang is in the meeting room now",
            [Task(kind="transfer", item="stapler", recipient="lee")],
            ("location", "zhang", "meeting_room"),
        ),
        (
            "FYI Zhou Yan is on leave today. Please make me a coffee.",
            [Task(kind="produce", item="coffee", recipient="lee")],
            ("availability", "zhou", "away"),
        ),
        (
            "Zhang's stapler is broken, get me another one",
            [Task(kind="transfer", item="stapler", recipient="lee")],
            ("condition", "zhang", "broken"),
        ),
    ],
)
def test_stated_fact_is_a_hint_not_a_party(
    parser: InstructionParser, text: str, tasks: list[Task], hint: tuple[str, str, str]
) -> None:
    frame = parser.parse(text, "lee")
    assert frame.tasks == tasks
    assert [(h.kind, h.person, h.value) for h in frame.hints] == [hint]
    assert "a fact" in frame.explain()


async def test_recipient_stays_the_requester_when_a_fact_names_someone(office: Office) -> None:
    run = await run_instruction(office, "lee", "Can you get me Dang's data cable? Wang is away")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert _handed(run) == [("data_cable:dang", "lee")]
    contacted = {r.action.contact for r in run.stm.trace.actions() if hasattr(r.action, "contact")}
    assert "wang" not in contacted


async def test_person_said_to_be_away_is_not_asked_and_memory_learns_it(office: Office) -> None:
    # Wang is in fact available and nearer than the others, but the requester said he is away
    run = await run_instruction(office, "yang", "Bring me a stapler please. Wang is away today")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    asked = [r.action.contact for r in run.stm.trace.actions() if r.action.type == "inquire"]  # type: ignore[union-attr]
    assert "wang" not in asked
    holder = [to for item, to in _handed(run) if item.startswith("stapler:")]
    assert holder == ["yang"]
    first = run.stm.trace.steps[0]
    assert first.reflection is not None
    updates = [u for u in first.reflection.updates if u.kind == "availability"]
    assert any(u.person == "wang" and u.available is False for u in updates)
    assert "Wang Fang is away" in (first.percept.summary if first.percept else "")


async def test_broken_item_owner_is_not_asked_for_it(office: Office) -> None:
    run = await run_instruction(office, "lee", "Zhang's stapler is broken, get me another one")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    asked = [r.action.contact for r in run.stm.trace.actions() if r.action.type == "inquire"]  # type: ignore[union-attr]
    assert "zhang" not in asked
    assert [to for _, to in _handed(run)] == ["lee"]


# -- the requester is never the lender or helper of their own request ---------------------------
async def test_requester_answering_the_group_chat_is_not_taken_as_helper(office: Office) -> None:
    # every known pen owner is away; the group chat is asked; the requester (who owns a pen)
    # says yes in the group — the assistant must not borrow their own pen back to them
    volunteered: list[str] = []
    requester_volunteers = answer_first_question(
        "office_work",
        "zhang",
        ChatRef(kind="group", id="office_work"),
        "Yes, I have one, you can borrow it.",
        volunteered,
    )

    run = await run_instruction(
        office,
        "zhang",
        "Could you bring me a stapler?",
        unavailable=("wang", "hu", "gao"),
        on_event=requester_volunteers,
    )
    assert volunteered
    assert not [h for h in _handed(run) if h[0] == "stapler:zhang"]
    assert run.stm.trace.outcome == "unachievable", run.stm.trace.summary


async def test_simulated_requester_does_not_volunteer_in_the_group(office: Office) -> None:
    run = await run_instruction(
        office, "zhang", "Could you bring me a stapler?", unavailable=("wang", "hu", "gao")
    )
    group_answers = [t for t in run.stm.dialogue if t.direction == "in" and t.chat.kind == "group"]
    assert all(t.person != "zhang" for t in group_answers)
    assert not _handed(run)


# -- requests by purpose map to item types by declared purposes ---------------------------------
@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("something to cut this with", "scissors"),
        ("Can you bring me something to cut this with?", "scissors"),
        ("smth to write with pls", "pen"),
        ("get me something to write on", "paper"),
        ("a few sheets of A4", "paper"),
        ("need something to charge my phone", "data_cable"),
        ("anything to read?", "book"),
    ],
)
def test_request_by_purpose(parser: InstructionParser, text: str, item: str) -> None:
    frame = parser.parse(text, "wang")
    assert frame.tasks == [Task(kind="transfer", item=item, recipient="wang")]


def test_purpose_no_item_serves_is_asked_not_guessed(parser: InstructionParser) -> None:
    frame = parser.parse("bring me something to juggle with", "lee")
    assert not frame.understood and frame.question


# -- typos keep their part of speech; "needs X's signature" is a signature ---------------------
@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("printe my file", Task(kind="print", item="file", owner="lee", recipient="lee")),
        (
            "pls printe the report for me",
            Task(kind="print", item="file", owner="lee", recipient="lee"),
        ),
        (
            "my contract needs Dr. Zhang's signature",
            Task(kind="sign", item="document", owner="lee", recipient="lee", actor="zhang"),
        ),
        (
            "This form needs Manager Mao's signature.",
            Task(kind="sign", item="document", owner="lee", recipient="lee", actor="mao"),
        ),
    ],
)
def test_typos_and_signature_nouns(parser: InstructionParser, text: str, task: Task) -> None:
    assert parser.parse(text, "lee").tasks == [task]


# -- ordinary words that are names are names only when used as names ----------------------------
@pytest.fixture(scope="module")
def word_names() -> InstructionParser:
    people = [("may", "May Lin"), ("mark", "Mark Tan"), ("will", "Will Ode"), ("ana", "Ana Bo")]
    office = parse_office(
        {
            "name": "words",
            "locations": [
                {"id": f"d{n}", "kind": "workstation", "name": f"D{n}", "x": 3 * n, "y": 0}
                for n in range(4)
            ],
            "item_types": [{"id": "stapler", "name": "stapler"}],
            "people": [
                {
                    "id": pid,
                    "name": name,
                    "location": f"d{n}",
                    "handle": f"@{pid}",
                    "owns": [] if pid == "ana" else [{"type": "stapler"}],
                }
                for n, (pid, name) in enumerate(people)
            ],
            "facilities": [],
            "groups": [{"id": "all", "name": "All", "members": [p for p, _ in people]}],
            "robot": {"home": "d0"},
        }
    )
    return InstructionParser(office)


@pytest.mark.parametrize(
    ("text", "owner", "recipient"),
    [
        ("Will you bring me a stapler?", None, "ana"),
        ("May I have a stapler?", None, "ana"),
        ("Will you please get May's stapler for me", "may", "ana"),
        ("Ask Will for his stapler and bring it to me", "will", "ana"),
        ("bring me Mark's stapler", "mark", "ana"),
        ("bring a stapler to Mark", None, "mark"),
        ("May I borrow Will's stapler?", "will", "ana"),
    ],
)
def test_word_names_only_as_names(
    word_names: InstructionParser, text: str, owner: str | None, recipient: str
) -> None:
    frame = word_names.parse(text, "ana")
    assert frame.tasks == [
        Task(kind="transfer", item="stapler", owner=owner, recipient=recipient)
    ], frame.question


# -- two plausible readings: one question, then act on the answer -------------------------------
def test_two_readings_give_one_question_then_the_answer_decides(
    parser: InstructionParser,
) -> None:
    frame = parser.parse("bring me Zhnag's stapler", "lee")
    assert not frame.understood and frame.question is not None
    assert frame.question.count("?") == 1 and "Zhang Wei or Zheng Hui" in frame.question
    frame = parser.parse_with_answers("bring me Zhnag's stapler", "lee", ["Zhang Wei"])
    assert frame.tasks == [Task(kind="transfer", item="stapler", owner="zhang", recipient="lee")]
