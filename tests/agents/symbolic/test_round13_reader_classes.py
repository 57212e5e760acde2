"""Blind round 13's reader classes, by mechanism, on sentences of our own against a small
county records archive no sentence was written for (``helpers.archive``): an operation whose
display name reads like a verb phrase ("print box labels", verb "tag"), a badge press that
makes visitor passes from nothing, a reel reader that digitises a glass slide into an
electronic scan, a mounting press that mounts a chart (the round's own office and sentences
were never read)."""

from __future__ import annotations

import functools

import pytest
from symbolic_run import run_instruction

from assistantx.core.office import Office, parse_office
from assistantx.core.task_schema import TaskFrame
from assistantx.sim.understanding import mentioned_requests
from helpers.archive import archive, raw_archive
from helpers.reading import frame_reader, parser_for

_parser = functools.partial(parser_for, archive)
_frame = frame_reader(archive, "ines")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.operation, t.recipient) for t in frame.tasks]


# -- 1. an operation's display name is no verb of a request ---------------------------------


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("print my document file, and also bring me a step ladder", "ines"),
        ("print my box list and bring me a kick step", "ines"),
        ("could you print my document for Priya? and a step ladder for me", "priya"),
    ],
)
def test_a_plain_print_is_one_print_not_the_label_run_too(text: str, recipient: str) -> None:
    """ "print" is the printer's verb; the label run whose *name* is "print box labels" is
    asked for by its own verb ("tag") or its product, never by the words of its name: one
    verb phrase, one task."""
    frame = _frame(text)
    assert frame.question is None, frame.question
    prints = [t for t in frame.tasks if t.kind == "print"]
    assert [(t.operation, t.recipient) for t in prints] == [("print", recipient)]
    assert [t.item for t in frame.tasks if t.kind == "transfer"] == ["step_ladder"]


@pytest.mark.parametrize(
    "text",
    ["tag my document", "print my document as box labels", "run off box labels from my box list"],
)
def test_the_label_run_is_still_asked_for_by_its_verb_or_product(text: str) -> None:
    assert _tasks(_frame(text)) == [("print", "doc_file", "tag", "ines")]


def test_both_operations_said_are_both_done() -> None:
    """Near-miss: the printer's verb and the label run's own verb, each said, are two tasks."""
    frame = _frame("print my box list, and tag it too")
    assert [t.operation for t in frame.tasks] == ["print", "tag"]


# -- 2. a named product chooses its operation over a generic making verb -------------------


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("print box labels from my box list and take them to Priya", "priya"),
        ("could you print me some box labels from my document", "ines"),
        ("get some box labels printed from my box list", "ines"),
    ],
)
def test_a_product_named_after_print_is_made_by_its_own_operation(
    text: str, recipient: str
) -> None:
    """The file goes to a keeper of the facility that offers the label run, not to the
    ordinary printer's keeper."""
    assert _tasks(_frame(text)) == [("print", "doc_file", "tag", recipient)]


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("get me a new visitor pass printed", "ines"),
        ("print me a visitor pass", "ines"),
        ("could you print a visitor pass for Priya", "priya"),
    ],
)
def test_a_made_thing_printed_is_made_by_the_press_that_makes_it(text: str, recipient: str) -> None:
    """A product made from nothing ("a visitor pass") is no file to print: it is made."""
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("produce", "pass_card", recipient)
    ]


@pytest.mark.parametrize(
    ("text", "operation"),
    [
        ("print my box list and take the printout to Priya", "print"),
        ("print my document", "print"),
    ],
)
def test_a_plain_print_stays_the_printers(text: str, operation: str) -> None:
    assert [t.operation for t in _frame(text).tasks] == [operation]


def test_a_made_thing_beside_a_file_is_still_asked_about() -> None:
    """Near-miss: "print my document and a visitor pass" is not read as either alone."""
    frame = _frame("print my document and a visitor pass")
    assert frame.tasks == [] and frame.question is not None


@pytest.mark.parametrize(
    ("text", "asked"),
    [
        ("Can you print box labels?", ["tag"]),
        ("Could you print box labels Ines Varga's document file at the tag printer?", ["tag"]),
        ("can you print me a visitor pass?", ["badge"]),
        ("can you get a visitor pass printed?", ["badge"]),
        ("could you print Ines's document?", ["print"]),
        ("could you tag my box list?", ["tag"]),
    ],
)
def test_a_colleague_reads_the_operation_from_the_product(text: str, asked: list[str]) -> None:
    """The simulated colleague answers from the office's operation table: the label run is
    asked for by its product, so only its guards say yes."""
    assert mentioned_requests(archive(), text) == asked


# -- 3. electronic products, and a facility as the doer --------------------------------------


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("Please scan my glass slide on the reel reader and send me the PDF.", "ines"),
        ("scan my slide and send me the PDF", "ines"),
        ("scan my slide. PDF to me is fine.", "ines"),
        ("scan my slide and email it to me", "ines"),
    ],
)
def test_the_file_a_scan_makes_goes_to_whom_it_is_sent(text: str, recipient: str) -> None:
    """ "send me the PDF" after a scan names who gets the scan's file; it is no forwarding
    of the requester's own file to themselves (asked "Who should I pass your file on to?")."""
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("copy", "slide", recipient)]


def test_an_owned_file_named_after_a_scan_is_still_a_file_of_its_own() -> None:
    """Near-miss: "send Priya my PDF" names the requester's own file, a second task."""
    frame = _frame("scan my slide and send Priya my PDF")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [
        ("copy", "ines"),
        ("send_file", "priya"),
    ]


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        ("Could the reel reader do my slide? PDF to me is fine.", "copy", "slide"),
        ("can the reel reader take my glass slide please", "copy", "slide"),
        ("could the mounting press handle my chart?", "heat", "chart"),
    ],
)
def test_a_facility_as_the_doer_asks_for_its_operation(text: str, kind: str, item: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [(kind, item, "ines")]


@pytest.mark.parametrize(
    "text", ["Can the reel reader do slides?", "can the reel reader take a slide?"]
)
def test_what_a_facility_can_do_in_general_moves_nothing(text: str) -> None:
    """Near-miss: nobody's item ("slides") is a question about the machine, not work."""
    assert _frame(text).tasks == []


@pytest.mark.parametrize("answer", ["Me.", "to me", "me please", "myself"])
def test_me_to_a_who_question_is_the_requester(answer: str) -> None:
    frame = _parser().parse_with_answers("send the box list", "ines", [answer])
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [("send_file", "ines", "ines")]
    frame = _parser().parse_with_answers("bring my tape gun", "ines", [answer])
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("transfer", "ines")]


@pytest.mark.parametrize(("answer", "to"), [("Priya", "priya"), ("Priya, not me", "priya")])
def test_another_name_to_a_who_question_is_that_person(answer: str, to: str) -> None:
    frame = _parser().parse_with_answers("send the box list", "ines", [answer])
    assert [t.recipient for t in frame.tasks] == [to]


def test_not_me_leaves_the_who_question_open() -> None:
    frame = _parser().parse_with_answers("send the box list", "ines", ["not me"])
    assert frame.tasks == [] and frame.question is not None


# -- 4. the recipient is also the operation's keeper -------------------------------------------


def _only_guard(guard: str) -> Office:
    raw = raw_archive()
    for f in raw["facilities"]:
        if f["id"] == "mount_press":
            f["guards"] = [guard]
    return parse_office(raw, "archive-one-guard")


@pytest.mark.parametrize("office", [archive(), _only_guard("oskar")])
async def test_the_operation_is_done_before_its_keeper_gets_the_item(office: Office) -> None:
    """ "mount my chart and then take it over to Oskar", Oskar a guard of the mounting
    press: the mount code is used at the press before the chart is handed to him."""
    run = await run_instruction(office, "ines", "mount my chart and then take it over to Oskar")
    codes = [
        (r.action.contact, r.action.purpose, r.action.operation)
        for r in run.stm.trace.actions()
        if r.action.type == "send_qr" and not r.refused
    ]
    assert codes == [
        ("ines", "deposit", None),
        ("oskar", "heat", "mount"),
        ("oskar", "collect", None),
    ]
    assert "chart:ines" in run.sim.world.heated
    assert run.stm.trace.outcome == "done"


# -- the file goes only to a keeper of the facility that runs the operation asked for -------


@pytest.mark.parametrize(
    ("text", "keepers"),
    [
        ("print box labels from my box list and take them to Priya", {"mira", "oskar"}),
        ("print my document file, and also bring me a step ladder", {"jonas"}),
    ],
)
async def test_the_file_goes_only_to_the_asked_operations_keepers(
    text: str, keepers: set[str]
) -> None:
    run = await run_instruction(archive(), "ines", text)
    sent_to = {
        r.action.target
        for r in run.stm.trace.actions()
        if r.action.type == "forward_file" and not r.refused
    }
    assert len(sent_to) == 1 and sent_to <= keepers, sent_to
    assert run.stm.trace.outcome == "done"
