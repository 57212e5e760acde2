"""Blind round 7's reader classes, by mechanism, on sentences of our own against a land
surveyors' practice no sentence was written for (the round's law firm and its sentences were
never read). Only what is asked for moves; a tool used on a paper is never handed over; a
request whose readings lead to different physical actions is asked about first."""

from __future__ import annotations

import functools
from collections.abc import Iterator

import pytest
from _offices import parser as other_parser
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office
from assistantx.core.task_schema import TaskFrame
from helpers.added_kinds import kind_added, signing_kind
from helpers.reading import frame_reader, parser_for
from helpers.surveyors import surveyors

Row = tuple[str, str | None, str | None, str]


_parser = functools.partial(parser_for, surveyors)
_frame = frame_reader(surveyors, "callum")


def _tasks(text: str, who: str = "callum") -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in _frame(text, who).tasks]


def _ops(text: str, who: str = "callum") -> list[tuple[str, str | None, str]]:
    return [(t.kind, t.operation, t.recipient) for t in _frame(text, who).tasks]


def _moves_nothing(frame: TaskFrame) -> None:
    assert frame.tasks == [], frame.tasks


# -- 1: a negation carried by a light verb, with its reason ----------------------------------
@pytest.mark.parametrize(
    "text",
    [
        "don't bother bringing me the spirit level, Otto's lending me his",
        "don't bother fetching a tripod, Bill is driving me to the site",
        "no need to fetch the measuring tape, I found mine in the van",
        "please don't trouble yourself getting Noor's level, we postponed the visit",
        "Don't bother with the tripod, the survey is cancelled",
        "skip fetching the tripod, Bill's got one in his car",
        "there's no need to get Bill's tripod since I'm staying in",
        "no point fetching the level, it's raining",
    ],
)
def test_a_negated_errand_with_its_reason_moves_nothing(text: str) -> None:
    frame = _frame(text)
    _moves_nothing(frame)
    assert frame.question is None and frame.decline is not None
    assert frame.decline_outcome == "done"


def test_a_request_after_the_negated_errand_is_still_read() -> None:
    text = "don't bother bringing the tripod, just bring me the spirit level please"
    assert _tasks(text) == [("transfer", "level", None, "callum")]


# -- 2: a failing item and "might need a new one" is offered, not fetched --------------------
@pytest.mark.parametrize(
    "text",
    [
        "my tripod is wobbly, I might need a new one",
        "The measuring tape is fraying. might need another one",
        "my spirit level keeps giving odd readings, I may need a new one",
        "the tripod's leg snapped, might need a replacement",
        "my measuring tape won't retract; probably need a new one",
        "I think I'll need a new spirit level, mine is cracked",
    ],
)
def test_a_failing_item_with_a_possible_need_is_offered(text: str) -> None:
    frame = _frame(text)
    _moves_nothing(frame)
    assert frame.question is not None and "Shall I" in frame.question


def test_the_offer_is_carried_out_on_yes_and_dropped_on_no() -> None:
    text = "my tripod is wobbly, I might need a new one"
    yes = _parser().parse_with_answers(text, "callum", ["yes please"])
    assert [(t.kind, t.item, t.recipient) for t in yes.tasks] == [("transfer", "tripod", "callum")]
    no = _parser().parse_with_answers(text, "callum", ["no, it's fine for now"])
    assert no.tasks == [] and no.decline_outcome == "done"


def test_a_request_beside_the_possible_need_is_carried_out() -> None:
    """ "..., can you bring one?" asks for it: "one" is the item the need named."""
    frame = other_parser("default").parse("maybe I need a new stapler, can you bring one?", "lee")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "stapler", "lee")]


def test_a_need_on_a_condition_is_still_only_noted() -> None:
    frame = _frame("if my tripod breaks I might need a new one")
    _moves_nothing(frame)
    assert frame.question is None and frame.decline is not None


# -- 3: a stamping tool used on a paper is a service, never a hand-over ----------------------
@pytest.mark.parametrize(
    "text",
    [
        "can you get my lease stamped with the embosser",
        "my affidavit needs the chartered stamp on it",
        "the will needs the stamp on it please",
        "please get my plan stamped with the practice seal",
        "could my tenancy agreement get the embosser on it",
        "can the embosser go on my lease?",
        "get the practice seal put on my lease",
        "I need my affidavit embossed",
        "my deed of variation needs stamping with the practice seal",
        "I've got a power of attorney here. Can you get it stamped with the embosser?",
        "the affidavit on my desk needs the practice seal",
        "please emboss my lease",
        "I need the embosser for my lease",
    ],
)
def test_a_tool_used_on_a_paper_stamps_the_paper(text: str) -> None:
    assert _tasks(text) == [("seal", "plan", "callum", "callum")]


@pytest.mark.parametrize(
    "text",
    [
        "please get it stamped with the embosser",
        "it needs the stamp on it",
        "get Tobias to stamp my lease with his embosser",
        "I need this stamped with the chartered stamp",
    ],
)
def test_the_stamping_tool_is_never_handed_over_for_a_paper(text: str) -> None:
    """Whatever else is read, the owned tool named as what stamps a paper does not move."""
    frame = _frame(text)
    assert not [t for t in frame.tasks if t.kind == "transfer" and t.item == "stamp"], frame
    assert frame.tasks or frame.question


@pytest.mark.parametrize(
    ("text", "stamper"),
    [
        ("get Tobias to stamp my lease with his embosser", "tobias"),
        ("have Ines stamp my lease", "ines"),
        ("my lease needs Tobias's embosser", "tobias"),
        ("can Ines put her stamp on my lease?", "ines"),
        ("take my lease to Ines to be stamped", "ines"),
    ],
)
def test_the_stamper_named_is_the_one_asked(text: str, stamper: str) -> None:
    """Whoever the words make the stamper (asked, owning the tool named, or the one the paper
    is taken to) stamps it, and the paper comes back to the requester."""
    assert [(t.kind, t.item, t.owner, t.actor, t.recipient) for t in _frame(text).tasks] == [
        ("seal", "plan", "callum", stamper, "callum")
    ]


@pytest.mark.parametrize(
    ("text", "signer"),
    [("have Wang sign my contract", "wang"), ("have Mao stamp my contract", "mao")],
)
def test_have_a_person_do_it_is_a_request_not_a_question(text: str, signer: str) -> None:
    frame = other_parser("default").parse(text, "lee")
    assert [(t.item, t.actor) for t in frame.tasks] == [("document", signer)], frame


async def test_in_the_office_the_paper_is_stamped_and_the_tool_stays_with_its_owner() -> None:
    run = await run_instruction(
        surveyors(), "callum", "can you get my lease stamped with the embosser"
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"sealed": ["plan:callum"]})
    assert run.sim.world.check({"holds": ["callum", "plan:callum"]})
    moved = {e.detail["item"] for e in run.sim.world.handovers()}
    assert "plan:callum" in moved  # the paper went to the stamp's owner and back
    assert not {i for i in moved if i.startswith("stamp:")}, moved


@pytest.mark.parametrize(
    "text",
    [
        "bring me the embosser",
        "could I borrow Ines's stamp",
        "put the stamp on my desk",  # "on" a place: the tool is moved, not used
        "please leave the embosser on the shelf for me",
        "could you ask Tobias to lend me his stamp",
        "I need the stamp for tomorrow",
        "bring me the embosser for the site visit",
    ],
)
def test_the_tool_asked_for_itself_is_still_fetched(text: str) -> None:
    assert [(t.kind, t.item) for t in _frame(text).tasks] == [("transfer", "stamp")]


# -- 4: operations of one machine told apart by their gerund, else asked -----------------------
@pytest.mark.parametrize(
    ("text", "op"),
    [
        ("my plan needs binding", "bind"),
        ("my contract wants scanning", "scan"),
        ("can you put my plan through the copier to scan it", "scan"),
        ("please take my survey plan to the copier, it needs binding", "bind"),
        ("take my certificate to the photocopier for copying", "copy"),
        ("my plan needs scanning on the copier", "scan"),
        ("my plan needs to be bound", "bind"),
        ("my certificate needs to be scanned", "scan"),
    ],
)
def test_the_operation_is_the_one_its_verb_or_gerund_names(text: str, op: str) -> None:
    assert [(t.operation, t.item) for t in _frame(text).tasks] == [(op, "plan")]


@pytest.mark.parametrize(
    ("text", "ops"),
    [
        ("photocopy and bind my plan", ["copy", "bind"]),
        ("scan my plan and then bind it", ["scan", "bind"]),
        ("please bind and scan my certificate", ["bind", "scan"]),
    ],
)
def test_several_operations_said_on_one_item_are_each_run(text: str, ops: list[str]) -> None:
    frame = _frame(text)
    assert [t.operation for t in frame.tasks] == ops
    assert {(t.item, t.owner) for t in frame.tasks} == {("plan", "callum")}


async def test_a_copy_and_a_binding_both_run_in_the_office() -> None:
    run = await run_instruction(surveyors(), "callum", "photocopy and bind my plan")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"copied": ["plan:callum"]})
    assert run.sim.world.check({"heated": ["plan:callum"]})


@pytest.mark.parametrize("text", ["take my plan to the copier", "put my contract in the copier"])
def test_a_machine_of_several_operations_named_alone_is_asked_about(text: str) -> None:
    frame = _frame(text)
    _moves_nothing(frame)
    assert frame.question is not None
    assert all(op in frame.question for op in ("copy", "scan", "bind")), frame.question


# -- 5: a modifier that is another item's word --------------------------------------------------
@pytest.mark.parametrize(
    ("text", "row"),
    [
        ("give Noor my draft contract", ("transfer", "plan", "callum", "noor")),
        ("please bring Bill the draft certificate from Ines", ("transfer", "plan", "ines", "bill")),
    ],
)
def test_an_item_word_before_another_item_modifies_it(text: str, row: Row) -> None:
    assert _tasks(text) == [row]


@pytest.mark.parametrize(
    "text",
    ["scan my draft contract", "could you scan my contract to PDF", "send my plan to PDF"],
)
def test_a_paper_to_pdf_is_its_scan(text: str) -> None:
    assert [(t.kind, t.item, t.operation) for t in _frame(text).tasks] == [("copy", "plan", "scan")]


# -- 6: "I need a PDF of it for <someone>" names the scan's recipient ------------------------
@pytest.mark.parametrize(
    "text",
    [
        "scan my plan, I need a PDF of it for Noor",
        "please scan my certificate. Noor needs a PDF of it",
        "can you scan my contract? I need a PDF of it for Noor",
    ],
)
def test_the_pdf_of_a_scan_goes_to_whom_it_is_for(text: str) -> None:
    assert _ops(text) == [("copy", "scan", "noor")]


@pytest.mark.parametrize(
    ("text", "rows"),
    [
        (
            "I need a copy of my plan for Noor and a PDF for Bill",
            [("copy", "copy", "noor"), ("copy", "scan", "bill")],
        ),
        (
            "a copy and a PDF of my certificate please",
            [("copy", "copy", "callum"), ("copy", "scan", "callum")],
        ),
        ("could you turn my plan into a PDF for Bill", [("copy", "scan", "bill")]),
    ],
)
def test_each_product_of_a_paper_named_is_made_for_whom_it_is_for(
    text: str, rows: list[tuple[str, str, str]]
) -> None:
    assert _ops(text) == rows


def test_a_scan_for_oneself_stays_with_the_requester() -> None:
    assert _ops("scan my plan, I need a PDF of it for the meeting") == [("copy", "scan", "callum")]


# -- 7: a self-correction after an ellipsis withdraws the first verb -------------------------
@pytest.mark.parametrize(
    ("text", "row"),
    [
        ("fetch Bill's tripod… actually, no, just print my draft", ("print", "drawing")),
        ("bring me Noor's level... actually no, just scan my plan", ("copy", "plan")),
        ("get me the tripod... no wait, just bind my plan", ("heat", "plan")),
        ("bring me the tripod - actually, just plot my drawing", ("print", "drawing")),
        ("fetch the level… no, actually print my draft", ("print", "drawing")),
        (
            "could you bring me the tripod? actually, make it the spirit level",
            ("transfer", "level"),
        ),
    ],
)
def test_only_the_corrected_request_runs(text: str, row: tuple[str, str]) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [row]
    assert all(t.owner in (None, "callum") for t in frame.tasks)


# -- 8: "I need it" after a fetch is the same errand ---------------------------------------
@pytest.mark.parametrize(
    ("text", "row"),
    [
        ("could you fetch Bill's tripod? I need the tripod", ("transfer", "tripod", "bill")),
        ("bring me Noor's spirit level. I need it", ("transfer", "level", "noor")),
        (
            "get me Callum's measuring tape please. I need the tape for the site visit",
            ("transfer", "tape", "callum"),
        ),
        ("can you get me a tripod? I need one for the site", ("transfer", "tripod", None)),
    ],
)
def test_the_need_said_again_is_no_second_task(text: str, row: tuple[str, str, str]) -> None:
    who = "otto"
    assert [(t.kind, t.item, t.owner) for t in _frame(text, who).tasks] == [row]


def test_a_need_of_someone_else_after_a_fetch_is_still_theirs() -> None:
    rows = _tasks("bring me Bill's tripod. Noor needs the spirit level too", "otto")
    assert ("transfer", "tripod", "bill", "otto") in rows
    assert any(r[1] == "level" and r[3] == "noor" for r in rows)


# -- 9: a send-out service "to" a colleague asks which was meant -----------------------------
@pytest.mark.parametrize(
    ("text", "verb"),
    [("courier my plan to Bill", "courier"), ("fax my contract to Noor", "fax")],
)
def test_sending_out_to_a_colleague_is_asked(text: str, verb: str) -> None:
    frame = _frame(text)
    _moves_nothing(frame)
    assert frame.question is not None and verb in frame.question.lower()
    assert "bring it to" in frame.question


def test_the_answer_chooses_the_hand_over_or_the_send_out() -> None:
    text = "courier my plan to Bill"
    inside = _parser().parse_with_answers(text, "callum", ["just bring it to him"])
    assert [(t.kind, t.item, t.owner, t.recipient) for t in inside.tasks] == [
        ("transfer", "plan", "callum", "bill")
    ]
    outside = _parser().parse_with_answers(text, "callum", ["send it out by courier"])
    assert [(t.operation, t.destination) for t in outside.tasks] == [("courier", "Bill")]


def test_a_place_outside_is_sent_without_asking() -> None:
    frame = _frame("courier my plan to the county land registry")
    assert [(t.operation, t.destination) for t in frame.tasks] == [
        ("courier", "the county land registry")
    ]


# -- 10: a task kind added to the live table is read from its words ------------------------
_ENDORSE = signing_kind(
    "endorse", "endorse", "endorsed", "endorser", words=("endorse", "endorsement")
)


@pytest.fixture
def endorse() -> Iterator[Office]:
    with kind_added(_ENDORSE):
        yield surveyors()


@pytest.mark.parametrize(
    "text",
    [
        "please get my plan endorsed by Noor",
        "can you get Noor to endorse my certificate",
        "I need Noor's endorsement on my contract",
    ],
)
def test_an_added_kind_is_read_by_its_words(endorse: Office, text: str) -> None:
    frame = InstructionParser(endorse).parse(text, "callum")
    assert [(t.kind, t.item, t.owner, t.actor) for t in frame.tasks] == [
        ("endorse", "plan", "callum", "noor")
    ]


def test_an_added_kind_with_no_doer_asks_who(endorse: Office) -> None:
    frame = InstructionParser(endorse).parse("please get my plan endorsed", "callum")
    _moves_nothing(frame)
    assert frame.question is not None and "Who" in frame.question


def test_the_kind_is_unknown_again_once_removed() -> None:
    frame = InstructionParser(surveyors()).parse("please get my plan endorsed by Noor", "callum")
    assert not [t for t in frame.tasks if t.kind == "endorse"]


# -- the same mechanisms on offices of other trades ------------------------------------------
@pytest.mark.parametrize(
    ("office", "who", "text", "row"),
    [
        # a negated errand and its reason; a possible replacement is offered, not fetched
        ("default", "lee", "don't bother bringing me a stapler, Zhang is lending me his", None),
        ("default", "lee", "no need to get me the scissors, I borrowed Sun's", None),
        # the default office's seal on a paper it does not list by that word
        ("default", "lee", "get my lease stamped with the company seal", ("seal", "document")),
        ("default", "lee", "my tenancy agreement needs the seal on it", ("seal", "document")),
        ("default", "lee", "put the seal on my desk", ("transfer", "seal")),
        # a gerund, a correction with its own verb, a need said again
        ("default", "lee", "my contract needs copying", ("copy", "document")),
        (
            "default",
            "lee",
            "bring me the stapler... actually no, just print my report",
            ("print", "file"),
        ),
        (
            "default",
            "lee",
            "could you get me Wang's stapler? I need the stapler",
            ("transfer", "stapler"),
        ),
        # harbour's scan makes a "scanned copy"; its file is also called "PDF"
        ("harbour", "may", "scan my contract to PDF", ("copy", "document")),
        ("harbour", "may", "my timesheet needs scanning", ("copy", "document")),
        ("harbour", "may", "give Mark my draft contract", ("transfer", "document")),
    ],
)
def test_the_mechanisms_hold_on_other_offices(
    office: str, who: str, text: str, row: tuple[str, str] | None
) -> None:
    frame = other_parser(office).parse(text, who)
    if row is None:
        assert frame.tasks == [] and frame.decline_outcome == "done", frame
    else:
        assert [(t.kind, t.item) for t in frame.tasks] == [row], frame


@pytest.mark.parametrize(
    "text",
    [
        "scan my contract, I need a scan of it for Mark",
        "please scan my invoice. Mark needs a scan of it",
        "can you scan my letter to pdf for Mark",
    ],
)
def test_a_scan_for_someone_on_another_office_goes_to_them(text: str) -> None:
    frame = other_parser("harbour").parse(text, "may")
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [("copy", "may", "mark")]


def test_a_replacement_on_another_office_is_offered() -> None:
    frame = other_parser("default").parse("my stapler is jammed, I might need a new one", "lee")
    assert frame.tasks == [] and frame.question and "Shall I bring you a stapler?" in frame.question
