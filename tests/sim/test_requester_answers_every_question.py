"""The simulated requester answers every kind of question the assistant asks, from the task's
truth, and asking never costs a task in evaluation.

The questions are the assistant's own: each row of ``ASKED`` is an instruction the symbolic
reader asks back about, with the question it asks (its wording, from
``agents/symbolic/reading``: frames.py, readings.py, operations.py, screen/judge.py) and
what the requester says to it; ``WORDED`` holds the ones no short instruction of these offices
brings about (the re-ask of ``agents/symbolic/decision.py``, two people of one name, a name
nobody has). Each kind is then played end to end through the evaluation harness: the assistant
asks once, the requester answers, the task is done.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import pytest

from assistantx.agents.symbolic.reading.parser import InstructionParser
from assistantx.core.office import Office, load_office, parse_office
from assistantx.core.settings import Settings
from assistantx.core.task_schema import Part
from assistantx.evaluation.dataset.tasks import Task
from assistantx.evaluation.harness import run_episode
from assistantx.evaluation.methods import MethodBuilder, MethodSpec
from assistantx.sim.requester import DONT_KNOW, NOTHING_TO_ADD, Wish, answer
from helpers.boathouse import boathouse, raw_boathouse
from helpers.clinic import clinic


@functools.cache
def workbench() -> Office:
    """The boathouse with a workbench that both charges and cleans headlamps: putting one
    there does not say which."""
    raw = raw_boathouse()
    raw["operations"].append(
        {"id": "clean", "name": "clean", "verbs": ["clean", "wipe"], "input": "headlamp"}
    )
    raw["facilities"].append(
        {
            "id": "workbench",
            "name": "workbench",
            "location": "tack_room",
            "operations": ["charge", "clean"],
            "guards": ["bram"],
        }
    )
    return parse_office(raw, "workbench")


OFFICES = {"default": load_office, "boathouse": boathouse, "clinic": clinic, "bench": workbench}
COURIER = Part(kind="heat", operation="courier", destination="the regional federation")


@dataclass(frozen=True)
class Asked:
    kind: str
    office: str
    requester: str
    instruction: str
    goal: tuple[dict[str, object], ...]
    question: str
    says: str
    parts: tuple[Part, ...] = ()


ASKED = (
    Asked(
        "where to",
        "boathouse",
        "ottilie",
        "courier my form out please",
        ({"heated": "form:ottilie"},),
        "Where should I courier it to? Please give me the name and address of the place.",
        "To the regional federation.",
        (COURIER,),
    ),
    Asked(
        "to whom",
        "boathouse",
        "kasia",
        "bring my radio",
        ({"holds": ["bram", "radio:kasia"]},),
        "Who should get your radio?",
        "Bram Okafor.",
    ),
    Asked(
        "to whom (a file)",
        "default",
        "lee",
        "please send my file",
        ({"received": ["zhou", "file:lee"]},),
        "Who should I pass your file on to?",
        "Zhou Yan.",
    ),
    Asked(
        "whose",
        "default",
        "lee",
        "bring me a document",
        ({"holds": ["lee", "document:zhang"]},),
        "Whose document do you mean?",
        "Zhang Wei's.",
    ),
    Asked(
        "whose and to whom",
        "default",
        "lee",
        "bring Zhou her stapler",
        ({"holds": ["zhou", "stapler:zhang"]},),
        "As far as I know, Zhou Yan has no stapler of their own. Whose stapler is it, and who "
        "should get it?",
        "It's Zhang Wei's stapler, for Zhou Yan.",
    ),
    Asked(
        "which person",
        "clinic",
        "ines",
        "print the rota for May",
        ({"printed": "file:ines"}, {"holds": ["may", "printout:ines"]}),
        "Do you mean May Oduya, or the month of May?",
        "May Oduya",
    ),
    Asked(
        "which person (not the person)",
        "clinic",
        "ines",
        "print the rota for May",
        ({"printed": "file:ines"}, {"holds": ["ines", "printout:ines"]}),
        "Do you mean May Oduya, or the month of May?",
        "the month of May",
    ),
    Asked(
        "which item",
        "default",
        "lee",
        "get it signed by Wang",
        ({"signed": ["document:lee", "wang"]}, {"holds": ["lee", "document:lee"]}),
        "Which item do you mean to be signed?",
        "The document.",
    ),
    Asked(
        "which service",
        "bench",
        "ottilie",
        "put my headlamp on the workbench",
        ({"heated": "headlamp:ottilie"}, {"holds": ["ottilie", "headlamp:ottilie"]}),
        "Which do you mean: charge or clean?",
        "charge",
        (Part(kind="heat", operation="charge"),),
    ),
    Asked(
        "who does it",
        "boathouse",
        "ottilie",
        "get my form signed",
        ({"signed": ["form:ottilie", "bram"]},),
        "Who should sign your form? Please tell me their name.",
        "Bram Okafor.",
    ),
    Asked(
        "whom a word meant",
        "boathouse",
        "ottilie",
        "fetch his stopwatch",
        ({"holds": ["ottilie", "stopwatch:bram"]},),
        "Who do you mean by 'his'? Please tell me their name.",
        "Bram Okafor.",
    ),
    Asked(
        "the whole request",
        "boathouse",
        "ottilie",
        "could you take care of it",
        ({"holds": ["ottilie", "stopwatch:bram"]},),
        "Sorry, I'm not sure what you need. What should I do, with which item, and for whom?",
        "I mean Bram Okafor's stopwatch, for me.",
    ),
    Asked(
        "the whole request (sent out)",
        "boathouse",
        "ottilie",
        "could you take care of it",
        ({"heated": "form:ottilie"},),
        "Sorry, I'm not sure what you need. What should I do, with which item, and for whom?",
        # a bare "the regional federation" names no address: asked since fix151b
        "I mean the form: please courier it to the regional federation in York.",
        (Part(kind="heat", operation="courier", destination="the regional federation in York"),),
    ),
    Asked(
        "shall I (yes)",
        "default",
        "lee",
        "Zhou needs a stapler",
        ({"holds": ["zhou", "stapler:*"]},),
        "Shall I bring a stapler to Zhou Yan?",
        "Yes, please.",
    ),
    Asked(
        "shall I (no)",
        "default",
        "lee",
        "does anyone have a stapler?",
        (),
        "As far as I know, Zhang Wei and Wang Fang have a stapler. Shall I bring you one?",
        "No, thanks.",
    ),
    # the truth does not hold the answer: said plainly, never a guess
    Asked(
        "where to (not known)",
        "boathouse",
        "ottilie",
        "courier my form out please",
        ({"heated": "form:ottilie"},),
        "Where should I courier it to? Please give me the name and address of the place.",
        DONT_KNOW,
    ),
    Asked(
        "who does it (not known)",
        "boathouse",
        "ottilie",
        "get my form signed",
        ({"holds": ["bram", "form:ottilie"]},),
        "Who should sign your form? Please tell me their name.",
        DONT_KNOW,
    ),
)


def _wish(case: Asked, office: Office) -> Wish:
    goal = [*case.goal, {"informed": case.requester}]
    return Wish.from_goal(office, case.requester, goal, case.parts)


@pytest.mark.parametrize("case", ASKED, ids=[c.kind for c in ASKED])
def test_the_question_asked_is_answered_from_the_truth(case: Asked) -> None:
    office = OFFICES[case.office]()
    asked = InstructionParser(office).parse(case.instruction, case.requester).question
    assert asked == case.question
    assert answer(office, _wish(case, office), case.question) == case.says


@pytest.mark.parametrize(
    ("question", "goal", "says"),
    [
        # decision.py re-asks once in other words
        (
            "Sorry, I still don't understand. Who should get your stapler?",
            {"holds": ["zhou", "stapler:lee"]},
            "Zhou Yan.",
        ),
        # readings.py: two people answer to one name
        (
            "Who do you mean by 'Wang': Wang Fang or Zhang Wei?",
            {"holds": ["lee", "stapler:wang"]},
            "Wang Fang",
        ),
        # readings.py: a name nobody in the office has
        (
            "I don't know anyone called 'Wanda' in this office. Who do you mean?",
            {"holds": ["wang", "stapler:lee"]},
            "Wang Fang.",
        ),
        # readings.py: a facility whose service the assistant cannot run
        (
            "Sorry, I can't help with the meeting room. I can fetch and deliver things, pass on "
            "files, and run errands at the office machines. What would you like me to do?",
            {"holds": ["lee", "stapler:wang"]},
            "I mean Wang Fang's stapler, for me.",
        ),
    ],
)
def test_the_questions_no_short_instruction_brings_about(
    question: str, goal: dict[str, object], says: str
) -> None:
    office = load_office()
    wish = Wish.from_goal(office, "lee", [goal, {"informed": "lee"}])
    assert answer(office, wish, question) == says


def test_without_a_task_the_place_they_wrote_is_the_answer_and_else_they_do_not_know() -> None:
    office = boathouse()
    where = "Where should I courier it to? Please give me the name and address of the place."
    wrote = Wish.from_words(office, "ottilie", "courier my form to the county office, please")
    assert answer(office, wrote, where) == "To the county office."
    silent = Wish.from_words(office, "ottilie", "courier my form out please")
    assert answer(office, silent, where) == NOTHING_TO_ADD


def test_the_where_to_question_asks_for_what_the_operation_sends_to() -> None:
    # a courier's place by the office file's words; an operation that says nothing asks for
    # the name of a place, never a number only a fax has
    raw = raw_boathouse()
    del raw["operations"][2]["destination_asked"]
    plain = parse_office(raw, "plain")
    asked = InstructionParser(plain).parse("courier my form out please", "ottilie").question
    assert asked == "Where should I courier it to? Please give me the name of the place."
    raw["operations"][2]["destination_asked"] = "the fax number"
    faxed = parse_office(raw, "faxed")
    asked = InstructionParser(faxed).parse("courier my form out please", "ottilie").question
    assert asked is not None and asked.endswith("Please give me the fax number.")


def _episode_task(case: Asked) -> Task:
    goal = [*case.goal, {"informed": case.requester}]
    return Task(
        id="t001",
        base="b1",
        level="L1",
        achievable=True,
        requester=case.requester,
        instruction=case.instruction,
        goal=goal,
        optimal_actions=1,
        spec=list(case.parts),
    )


SUCCEED = [c for c in ASKED if c.says != DONT_KNOW and c.says != "No, thanks."]


@pytest.mark.parametrize("case", SUCCEED, ids=[c.kind for c in SUCCEED])
async def test_the_assistant_asks_once_and_the_task_is_done(case: Asked) -> None:
    office = OFFICES[case.office]()
    task = _episode_task(case)
    builder = MethodBuilder(MethodSpec("ppdr"), office, Settings())
    episode = await run_episode(task, 0, office, builder)
    asked = [r.action for r in episode.trace.actions() if r.action.type == "inquire"]
    to_requester = [a for a in asked if getattr(a, "contact", None) == case.requester]
    assert [getattr(a, "question", None) for a in to_requester] == [case.question]
    assert episode.trace.outcome == "done", episode.trace.summary
    assert all(episode.milestones), (episode.milestones, episode.trace.summary)
    for part in case.parts:
        if part.destination:  # sent where the requester said, not where a guess would go
            assert f"to {part.destination}" in (episode.trace.summary or "")
