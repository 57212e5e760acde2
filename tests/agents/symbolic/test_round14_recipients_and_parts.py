"""Blind round 14's reader classes about who receives and which parts a request has, on
sentences of our own against a ceramics studio's design office no sentence was written for
(``helpers.kilnworks``; the round's own office and sentences were never read): a title alias
with its article ("the Provost"), a person's own place as where they receive ("leave one at
her desk"), a colleague's item asked for by "theirs", a part of a request that cannot be
resolved, and "for her" after a printed product."""

from __future__ import annotations

import functools

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic.evidence import gather
from assistantx.agents.symbolic.plan_parts import left_out
from assistantx.agents.symbolic.planning import Agenda, Planner
from assistantx.agents.symbolic.reading.parts import asked_part
from assistantx.agents.symbolic.roles import Roles
from assistantx.core.task_schema import Task, TaskFrame
from assistantx.memory.graph import LongTermMemory
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.kilnworks import kilnworks
from helpers.reading import frame_reader, parser_for

_parser = functools.partial(parser_for, kilnworks)
_frame = frame_reader(kilnworks, "kit")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient, t.actor) for t in frame.tasks]


# -- 1. a title alias with its article is the person --------------------------------------


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        ("print my agenda and give it to the Provost", [("print", "agenda", "oona", None)]),
        ("print my agenda for the Provost", [("print", "agenda", "oona", None)]),
        ("take my report to the provost please", [("transfer", "report", "oona", None)]),
        ("get the Provost to sign my report", [("sign", "report", "kit", "oona")]),
        ("bring me the Provost's calculator", [("transfer", "calculator", "kit", None)]),
    ],
)
def test_a_title_declared_with_its_article_names_the_person(
    text: str, tasks: list[tuple[str, str | None, str | None, str | None]]
) -> None:
    """ "the Provost" is declared for Oona Pike: written with its article it is her, as
    recipient, signer or owner; never "Do you mean Oona Pike, or the provost?"."""
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert _tasks(frame) == tasks


def test_the_owner_named_by_a_title_alias_is_the_owner() -> None:
    frame = _frame("bring me the Provost's calculator")
    assert [t.owner for t in frame.tasks] == ["oona"]


@pytest.mark.parametrize(
    "text", ["print my agenda and give it to the Provost", "take my report to the Provost"]
)
def test_the_guard_knows_the_title_alias_as_the_recipient(text: str) -> None:
    assert named_recipients(kilnworks(), memory("kit", text)) == {"oona"}


@pytest.mark.parametrize(
    "text", ["what does a provost do?", "is there a provost here?", "who is the provost?"]
)
def test_a_question_about_the_title_moves_nothing(text: str) -> None:
    """Near-miss: a question naming the title is still a question."""
    assert _frame(text).tasks == []


async def test_a_printout_for_the_title_alias_is_handed_to_her() -> None:
    run = await run_instruction(kilnworks(), "kit", "print my agenda and give it to the Provost")
    handed = [
        (r.action.contact, r.action.purpose)
        for r in run.stm.trace.actions()
        if r.action.type == "send_qr" and not r.refused
    ]
    assert ("oona", "collect") in handed
    assert not [r for r in run.stm.trace.actions() if r.refused]


# -- 2. a person's own place names them as the recipient, for the reader and the guard ----

AT_THEIR_PLACE = [
    ("Sunniva wants a hole punch, drop one at her desk", "sunniva"),
    ("Sunniva wants a hole punch. Could you drop one at her desk?", "sunniva"),
    ("Teodor needs a calculator, could you drop one on his desk", "teodor"),
    ("Bram asked for a hole punch, please put one in his office", "bram"),
    ("drop a hole punch on Sunniva's desk", "sunniva"),
    ("leave my calculator in Bram's tray", "bram"),
]


@pytest.mark.parametrize(("text", "to"), AT_THEIR_PLACE)
def test_her_place_makes_her_the_recipient(text: str, to: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [t.recipient for t in frame.tasks] == [to]


@pytest.mark.parametrize(
    "text",
    [
        *(text for text, _ in AT_THEIR_PLACE),
        "print my agenda and give it to the Provost",
        "Sunniva asked for the agenda, print it for her",
        "bring Teodor my calculator",
        "can you drop my calculator off for Bram",
    ],
)
def test_whoever_the_reader_hands_over_to_the_guard_was_told_of(text: str) -> None:
    """One rule (``core.receiving_place``) for the reader and the guard: every recipient of
    the reader's frame other than the requester is someone the guard counts as named."""
    frame = _frame(text)
    receivers = {t.recipient for t in frame.tasks} - {"kit", None}
    assert receivers, frame
    assert receivers <= named_recipients(kilnworks(), memory("kit", text)), text


@pytest.mark.parametrize(
    "text",
    [
        "Sunniva and Bram want a hole punch, drop one at her desk",  # whose desk?
        "drop a hole punch at her desk",  # nobody named
    ],
)
def test_a_place_pronoun_with_no_one_person_before_it_is_asked(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None


@pytest.mark.parametrize(
    ("text", "named"),
    [
        ("bring me the hole punch from Sunniva's desk", set()),  # a source, not a recipient
        ("Sunniva wants a hole punch", set()),  # a wisher only
        ("bring me Sunniva's calculator", set()),  # an owner only
        ("Sunniva and Bram want a hole punch, drop one at her desk", set()),
    ],
)
def test_the_guard_names_no_one_else_from_a_place(text: str, named: set[str]) -> None:
    """Near-misses: a place one takes from, a wish, an owner, or an ambiguous "her" name no
    recipient for the guard."""
    assert named_recipients(kilnworks(), memory("kit", text)) == named


async def test_the_item_left_at_her_desk_is_handed_to_her() -> None:
    """The run that fetched a colleague's hole punch and then had the hand-over refused ("not
    someone you named to receive it") now hands it over."""
    run = await run_instruction(
        kilnworks(), "kit", "Sunniva wants a hole punch, drop one at her desk"
    )
    assert not [r for r in run.stm.trace.actions() if r.refused]
    handed = [
        (r.action.contact, r.action.purpose)
        for r in run.stm.trace.actions()
        if r.action.type == "send_qr"
    ]
    assert handed[-1] == ("sunniva", "collect")


# -- 4. a part of the request is never silently dropped -----------------------------------


@pytest.mark.parametrize(
    ("text", "part"),
    [
        ("get my report past legal and then off to the head office", "off to the head office"),
        ("vet my report, then over to the annex", "over to the annex"),
        ("vet my report and then send it out", "send it out"),
        ("Vet my report. Then off to the county office please", "off to the county office"),
        ("courier my report to the head office and vet it", "courier my report"),
    ],
)
def test_a_part_no_task_carries_is_asked_about(text: str, part: str) -> None:
    """The review is read; the sending out is not: the whole request waits for an answer
    that names the part, never the review alone reported as done."""
    frame = _frame(text)
    assert frame.tasks == []
    assert frame.question is not None and part in frame.question, frame.question
    assert asked_part(frame.question) is not None


@pytest.mark.parametrize(
    ("text", "answer"),
    [
        (
            "get my report past legal and then off to the head office",
            "courier it to the Leeds head office",
        ),
        ("vet my report and then send it out", "fax it to the county office"),
    ],
)
def test_the_answer_takes_the_place_of_the_part(text: str, answer: str) -> None:
    frame = _parser().parse_with_answers(text, "kit", [answer])
    assert frame.question is None, frame.question
    assert [(t.operation, t.destination is not None) for t in frame.tasks] == [
        ("vet", False),
        (answer.split()[0], True),
    ]


@pytest.mark.parametrize(
    ("text", "operations"),
    [
        ("vet my report and then courier it to the Leeds head office", ["vet", "courier"]),
        ("get my report past legal and then fax it to the head office", ["vet", "fax"]),
        ("courier my report to the Leeds head office", ["courier"]),
        ("get my report past legal", ["vet"]),
    ],
)
def test_each_service_said_is_its_own_task(text: str, operations: list[str]) -> None:
    """The send-out said in the second clause is that clause's task, never the review run
    twice with the sending left out."""
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [t.operation for t in frame.tasks] == operations


@pytest.mark.parametrize(
    "text",
    [
        "print my agenda and give it to the Provost",
        "print my agenda, then bring it to me",
        "bring me a calculator from the store cupboard",
        "get my calculator out of the post room and bring it to me",
        "could you take my report to the legal desk",
        "please bring my report to Bram's desk and then to the Provost",
    ],
)
def test_requests_whose_every_part_is_read_are_not_asked(text: str) -> None:
    """Near-misses: a "to" naming a person, "me" or a place of the office, a purpose, a
    facility an item is taken from."""
    frame = _frame(text)
    assert frame.question is None or asked_part(frame.question) is None, frame.question


async def test_nothing_moves_before_the_part_is_answered() -> None:
    """The run asks about the part first; with no answer that settles it, nothing physical
    happens and the outcome is not done."""
    run = await run_instruction(
        kilnworks(), "kit", "get my report past legal and then off to the head office"
    )
    actions = [r.action for r in run.stm.trace.actions()]
    assert actions[0].type == "inquire" and actions[0].contact == "kit"
    assert not [a for a in actions if a.type in ("move", "send_qr", "forward_file")]
    assert actions[-1].type == "stop" and actions[-1].outcome != "done"


# -- 4b. where the plan is built: every task of the reading has its steps -----------------


def _agenda(frame: TaskFrame) -> Agenda:
    office = kilnworks()
    planner = Planner(office, Roles(office, office.distance))
    return planner.agenda(frame, LongTermMemory(office), gather(memory("kit", "x"), office), 0.0)


def test_a_send_out_with_nowhere_to_go_stops_the_whole_plan() -> None:
    """A frame from anywhere (a hybrid reasoner's, an answer's re-reading) with a send-out
    that has no destination: nothing of it runs, not the review before it either."""
    frame = TaskFrame(
        requester="kit",
        tasks=[
            Task(kind="heat", item="report", owner="kit", recipient="kit", operation="vet"),
            Task(kind="heat", item="report", owner="kit", recipient="kit", operation="courier"),
        ],
    )
    agenda = _agenda(frame)
    assert agenda.active is None
    assert {t.status for t in agenda.tasks} == {"unachievable"}
    assert "where to send" in agenda.tasks[1].reason


def test_a_plan_with_every_part_runs() -> None:
    frame = TaskFrame(
        requester="kit",
        tasks=[
            Task(kind="heat", item="report", owner="kit", recipient="kit", operation="vet"),
            Task(
                kind="heat",
                item="report",
                owner="kit",
                recipient="kit",
                operation="courier",
                destination="the head office",
            ),
        ],
    )
    agenda = _agenda(frame)
    assert [t.status for t in agenda.tasks] == ["active", "active"]


def test_the_parts_check_names_a_task_with_no_step() -> None:
    class Compiled:
        def __init__(self, task: Task, phases: list[object]) -> None:
            self.task, self.phases = task, phases

    report = Task(kind="heat", item="report", owner="kit", recipient="kit", operation="vet")
    assert left_out(kilnworks(), [Compiled(report, [object()])]) is None
    assert left_out(kilnworks(), [Compiled(report, [object()]), Compiled(report, [])])


# -- 3. "can someone lend me theirs": anyone's item ----------------------------------------


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("my hole punch is broken, can someone lend me theirs", "hole_punch"),
        ("my hole punch is broken. Could somebody lend me theirs?", "hole_punch"),
        ("my hole punch jammed, could one of you lend me yours?", "hole_punch"),
        ("my calculator died, does anyone have a spare I could borrow", "calculator"),
        ("my calculator died, does anyone have a spare calculator I could borrow", "calculator"),
    ],
)
def test_theirs_after_someone_is_anyones(text: str, item: str) -> None:
    """Nobody's own item is named: whoever has one (their own yes), or the office's
    ownerless one; never "I'm not sure what you need"."""
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, None, "kit")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "can someone lend me theirs",  # no item said anywhere: asked
        "Sunniva has a hole punch, could she lend me hers",  # hers is Sunniva's, not anyone's
    ],
)
def test_theirs_with_no_item_or_a_named_owner_is_not_anyones(text: str) -> None:
    """Near-misses: nothing is fetched from whoever has one."""
    assert [t for t in _frame(text).tasks if t.owner is None] == []


@pytest.mark.parametrize(
    "text", ["does anyone have a spare?", "does anyone have a spare hole punch?"]
)
def test_asking_who_has_a_spare_moves_nothing(text: str) -> None:
    """Near-miss: a question with no borrowing in it is answered in words."""
    assert _frame(text).tasks == []


async def test_a_colleagues_hole_punch_is_borrowed_with_their_own_yes() -> None:
    run = await run_instruction(
        kilnworks(), "kit", "my hole punch is broken, can someone lend me theirs"
    )
    actions = [r.action for r in run.stm.trace.actions() if not r.refused]
    asked = [a.contact for a in actions if a.type == "inquire"]
    deposits = [a for a in actions if a.type == "send_qr" and a.purpose == "deposit"]
    assert asked and "kit" not in asked
    assert [a.item.split(":")[1] for a in deposits] == asked[:1]
    assert actions[-1].type == "stop" and actions[-1].outcome == "done"


async def test_the_ownerless_calculator_is_taken_first() -> None:
    run = await run_instruction(
        kilnworks(), "kit", "my calculator died, does anyone have a spare I could borrow"
    )
    items = [r.action.item for r in run.stm.trace.actions() if r.action.type == "send_qr"]
    assert items and set(items) == {"calculator:store_cupboard"}


# -- 5. "for her" after a printed product, and a title in two-part sentences --------------


@pytest.mark.parametrize(
    ("text", "to"),
    [
        ("Sunniva asked for the agenda, print it for her", "sunniva"),
        ("Sunniva needs the agenda, can you print it for her", "sunniva"),
        ("Sunniva needs a printout of my agenda, print one for her", "sunniva"),
        ("Teodor is chairing today, print my agenda for him please", "teodor"),
    ],
)
def test_a_printout_for_her_is_one_print_handed_to_her(text: str, to: str) -> None:
    """The need said first is met by the print: one print for her, no file sent besides
    and no second printout."""
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("print", "agenda", to)]


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        (
            "print my agenda and give it to the Provost, and bring me a calculator",
            [("print", "agenda", "oona", None), ("transfer", "calculator", "kit", None)],
        ),
        (
            "bring me a calculator and print my agenda for the Provost",
            [("transfer", "calculator", "kit", None), ("print", "agenda", "oona", None)],
        ),
        (
            "print the agenda for the Provost and give her my calculator",
            [("print", "agenda", "oona", None), ("transfer", "calculator", "oona", None)],
        ),
    ],
)
def test_a_title_in_a_two_part_sentence_names_its_part(
    text: str, tasks: list[tuple[str, str | None, str | None, str | None]]
) -> None:
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert _tasks(frame) == tasks


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("send Sunniva my agenda and print it for her", ["send_file", "print"]),
        ("Sunniva needs my calculator, bring it to her", ["transfer"]),
        ("print my agenda for Sunniva and bring her my calculator", ["print", "transfer"]),
    ],
)
def test_two_errands_said_as_requests_stay_two(text: str, kinds: list[str]) -> None:
    """Near-misses: only a need gives way to the work that meets it."""
    assert [t.kind for t in _frame(text).tasks] == kinds


def test_her_with_nobody_named_is_still_asked() -> None:
    frame = _frame("print my agenda for her")
    assert frame.tasks == [] and frame.question is not None
