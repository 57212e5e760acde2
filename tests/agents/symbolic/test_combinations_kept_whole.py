"""Combinations of two requests read whole, unlisted everyday paper nouns, and answers that
keep what the request said (blind rounds 34 to 36's classes; their offices and sentences were
never read):

- a request clause is never silently dropped: "my report" where the office's personal paper
  is a "document" with other names is that paper when it is the only candidate (a file when
  it is forwarded or emailed), and is asked about when the office has several;
- "... and on the way ...", "... and while you're passing ...", "... and on your way back
  ...", "... and have the Boss sign ..." join a second request to the first;
- after a clarifying question, a re-read that gives a thing another owner than the request
  said, or hands nothing to a colleague it said gets something, is never acted on; the
  simulated requester says whose the thing is ("My stapler.", "Brook Tamsin's charger.").
"""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.kept_roles import contradicts, said_roles
from assistantx.core.task_schema import Task, TaskFrame
from assistantx.sim.requester import Wish, answer
from helpers.design_studio import design_studio, two_papers_studio
from helpers.reading import answered_reader, frame_reader, parser_for

_frame = frame_reader(design_studio, "nina")
_two = frame_reader(two_papers_studio, "nina")
_answered = answered_reader(design_studio, "nina")
_answered_two = answered_reader(two_papers_studio, "nina")

Row = tuple[str, str | None, str | None, str | None]


def _tasks(frame: TaskFrame) -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


_PAPER_TO_OLIVE: Row = ("transfer", "document", "nina", "olive")
_TEA: Row = ("produce", "tea", None, "nina")


# -- D1: the requester's paper in an everyday noun ------------------------------------------
@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        ("Take my report to Olive, then bring me a cuppa.", [_PAPER_TO_OLIVE, _TEA]),
        ("Take my memo to Olive and then make me a cup of tea", [_PAPER_TO_OLIVE, _TEA]),
        ("Bring me a cuppa and take my letter to Olive", [_TEA, _PAPER_TO_OLIVE]),
        ("Give Olive my draft proposal", [_PAPER_TO_OLIVE]),
        ("Take my expenses report to Olive, then bring me a brew.", [_PAPER_TO_OLIVE, _TEA]),
        ("Email my report to Olive", [("send_file", "file", "nina", "olive")]),
        ("Forward my notes to Olive please", [("send_file", "file", "nina", "olive")]),
        ("Print my minutes", [("print", "file", "nina", "nina")]),
    ],
)
def test_the_requesters_paper_in_an_everyday_noun_is_the_offices_one_paper(
    text: str, tasks: list[Row]
) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(frame) == tasks, frame


def test_a_signature_on_my_letter_is_on_the_paper() -> None:
    frame = _frame("can the Boss sign my letter?")
    assert [(t.kind, t.item, t.owner, t.actor) for t in frame.tasks] == [
        ("sign", "document", "nina", "dora")
    ], frame


@pytest.mark.parametrize(
    ("text", "phrase"),
    [
        ("Take my memo to Olive, then bring me a cuppa.", "my memo"),
        ("Bring me a cuppa and take my letter to Olive", "my letter"),
        ("Take my draft report to Olive and bring me Brook's charger", "my draft report"),
    ],
)
def test_where_the_office_has_several_papers_the_clause_is_asked_never_dropped(
    text: str, phrase: str
) -> None:
    frame = _two(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert f"“{phrase}”" in frame.question


@pytest.mark.parametrize(
    ("answer", "item"), [("the certificate", "certificate"), ("document", "document")]
)
def test_the_answer_takes_the_papers_place_and_keeps_my(answer: str, item: str) -> None:
    frame = _answered_two("Take my memo to Olive, then bring me a cuppa.", [answer])
    assert _tasks(frame) == [("transfer", item, "nina", "olive"), _TEA], frame


@pytest.mark.parametrize(
    "text",
    [
        "Take my document to Olive, then bring me a cuppa.",
        "Take my report card to Olive",  # a compound: no paper
        "Take Brook's report to Olive",  # not the requester's own
    ],
)
def test_near_misses_keep_their_reading(text: str) -> None:
    before = _frame(text)
    if "document" in text:
        assert _tasks(before) == [_PAPER_TO_OLIVE, _TEA], before
    else:
        assert before.tasks == [] and before.question is not None, before


@pytest.mark.parametrize(
    "text", ["my report is on my desk", "Thanks for taking my report to Olive", "I wrote my memo"]
)
def test_a_statement_or_thanks_about_my_report_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame


# -- D2: linkers that join a second request ---------------------------------------------------
_CHARGER: Row = ("transfer", "charger", "brook", "nina")
_PRINT: Row = ("print", "file", "nina", "nina")


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "Bring me Brook's charger, and on the way print my referral PDF for me.",
            [_CHARGER, _PRINT],
        ),
        (
            "Bring me Brook's charger, and while you're passing, print my pdf for me.",
            [_CHARGER, _PRINT],
        ),
        ("Bring me Brook's charger and on your way back print my pdf", [_CHARGER, _PRINT]),
        ("Print my pdf, and on the way back bring me Brook's charger.", [_PRINT, _CHARGER]),
        ("Bring me Brook's charger and on the way back make me a cuppa", [_CHARGER, _TEA]),
        (
            "Bring me Brook's charger, and while you're there, could you print my pdf?",
            [_CHARGER, _PRINT],
        ),
        (
            "Can you give Fiona my stapler and have the Boss sign my form?",
            [("transfer", "stapler", "nina", "fiona"), ("sign", "document", "nina", "nina")],
        ),
        (
            "Bring me Brook's charger and let Dora sign my form",
            [_CHARGER, ("sign", "document", "nina", "nina")],
        ),
    ],
)
def test_a_linker_joins_a_second_request(text: str, tasks: list[Row]) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert _tasks(frame) == tasks, frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "Bring Brook's charger to Olive on the way back",
            [("transfer", "charger", "brook", "olive")],
        ),
        ("Bring me Brook's charger on your way", [_CHARGER]),
        ("have Dora sign my form", [("sign", "document", "nina", "nina")]),
    ],
)
def test_one_request_with_such_words_stays_one(text: str, tasks: list[Row]) -> None:
    assert _tasks(_frame(text)) == tasks


# -- D3: answers keep what the request said ---------------------------------------------------
def test_a_reread_that_loses_the_said_owner_or_recipient_contradicts_the_request() -> None:
    lex = parser_for(design_studio).lex
    roles = said_roles([lex.read("Can you give Fiona my stapler and read my form?")], "nina")
    assert roles.owners == {"stapler": {"nina"}, "document": {"nina"}}
    assert roles.recipients == {"fiona"}
    anyones = Task(kind="transfer", item="stapler", recipient="nina")
    assert contradicts(TaskFrame(requester="nina", tasks=[anyones]), roles)
    mine = Task(kind="transfer", item="stapler", owner="nina", recipient="nina")
    assert contradicts(TaskFrame(requester="nina", tasks=[mine]), roles)  # Fiona gets nothing
    kept = Task(kind="transfer", item="stapler", owner="nina", recipient="fiona")
    assert not contradicts(TaskFrame(requester="nina", tasks=[kept]), roles)
    brook = said_roles(
        [lex.read("Bring me Brook's charger, and as you go by print my pdf")], "nina"
    )
    anyone = Task(kind="transfer", item="charger", recipient="nina")
    assert contradicts(TaskFrame(requester="nina", tasks=[anyone]), brook)


@pytest.mark.parametrize(
    "text",
    [
        "Bring me Brook's charger, and as you go by print my pdf for me.",
        "Can you give Fiona my stapler and see that the Boss signs my form?",
    ],
)
def test_a_bare_answer_never_moves_another_colleagues_thing(text: str) -> None:
    asked = _frame(text)
    assert asked.question is not None, asked
    noun = "charger" if "charger" in text else "stapler"
    frame = _answered(text, [f"The {noun}."])
    assert all(
        t.owner == ("brook" if noun == "charger" else "nina") for t in frame.tasks if t.item == noun
    ), frame
    if noun == "stapler":
        assert all(t.recipient == "fiona" for t in frame.tasks if t.item == noun), frame


@pytest.mark.parametrize(
    ("goal", "said"),
    [
        (
            [{"holds": ["nina", "charger:brook"]}, {"printed": ["file:nina"]}],
            "Brook Tamsin's charger.",
        ),
        (
            [{"holds": ["fiona", "stapler:nina"]}, {"signed": ["document:nina", "dora"]}],
            "My stapler.",
        ),
        ([{"holds": ["nina", "charger:*"]}], "The charger."),
    ],
)
def test_the_simulated_requester_says_whose_the_thing_is(goal: list, said: str) -> None:
    office = design_studio()
    wish = Wish.from_goal(office, "nina", goal)
    item = said.rstrip(".").split()[-1]
    question = f"Sorry, I'm not sure what you want me to do with the {item}. Could you tell me?"
    assert answer(office, wish, question) == said


def test_the_owner_said_in_the_answer_is_kept_through_the_reread() -> None:
    text = "Bring me Brook's charger, and as you go by print my pdf for me."
    frame = _answered(text, ["Brook Tamsin's charger."])
    assert sorted(_tasks(frame)) == sorted([_CHARGER, _PRINT]), frame


@pytest.mark.parametrize(
    "text",
    [
        "have the Boss sign my form",
        "Have the Boss sign my form please",
        "Have the boss sign my letter",
    ],
)
def test_have_a_role_sign_is_a_request_that_they_sign(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.actor) for t in frame.tasks] == [
        ("sign", "document", "nina", "dora")
    ], frame


@pytest.mark.parametrize("text", ["Have the boss signed my form?", "Has the Boss signed my form?"])
def test_have_the_boss_signed_is_still_a_question(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
