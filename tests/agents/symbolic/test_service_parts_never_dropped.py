"""Every service part of a request is done, or told before anything moves: two services asked
on one thing ("I need my document scanned and stamped", "get it copied and stamped", "my
document printed and copied") each become a task, or the request asks or declines saying
which part cannot be done here. Three mechanisms lost parts before: a first participle on
"it" with nothing said yet (shared_object.waits_for_object: the next participle finds the
thing), a second participle after a service that read another type for the thing said
(frames: the paper as said), and a second service's task turned into the first one's
operation where its own does not take the thing (operations: left to be refused as its own
work). A service whose tool nobody in the office has (harbour has no seal) is told first
(toolless_parts): alone, declined with why; beside others, "Shall I still ...?"."""

from __future__ import annotations

import itertools

import pytest

from assistantx.core import language
from assistantx.core.office import Office
from assistantx.core.task_schema import TaskFrame, operation_of
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import OfficeOf, answered_reader, frame_reader, parser_for

_DEFAULT = frame_reader(default_office, "lee")
_HARBOUR = frame_reader(harbour_office, "may")

_FORMS = ("I need my document {} and {}", "get it {} and {}", "can you get my document {} and {}")


def _services(office: Office) -> list[tuple[str, str]]:
    """(what runs it: an operation id or a task kind, its past participle) of the office's
    services on a thing: its operations, and stamping and signing by a colleague."""
    found = [
        (op.id, language.past_participle(op.verbs[0].split()[0]))
        for op in office.operations
        if op.input and office.runnable(op.id) and not op.sends_out and op.verbs
    ]
    return [*found, ("seal", "stamped"), ("sign", "signed")]


def _run(office: Office, frame: TaskFrame) -> set[str | None]:
    return {t.kind for t in frame.tasks} | {operation_of(office, t) for t in frame.tasks}


@pytest.mark.parametrize(("office", "who"), [(default_office, "lee"), (harbour_office, "may")])
def test_every_service_asked_is_a_task_or_the_request_asks_or_declines(
    office: OfficeOf, who: str
) -> None:
    built, parser = office(), parser_for(office)
    lost = []
    for (a, said_a), (b, said_b) in itertools.permutations(_services(built), 2):
        for form in _FORMS:
            text = form.format(said_a, said_b)
            frame = parser.parse(text, who)
            if frame.question or frame.decline:
                continue  # told or asked before anything moves
            if not {a, b} <= _run(built, frame) or len(frame.tasks) < 2:
                lost.append((text, [(t.kind, t.item) for t in frame.tasks]))
    assert not lost, lost


@pytest.mark.parametrize(
    ("text", "got"),
    [
        ("get it copied and stamped", [("copy", "document"), ("seal", "document")]),
        ("get this copied and signed by Zhang", [("copy", "document"), ("sign", "document")]),
        ("I need my document printed and copied", [("print", "file"), ("copy", "document")]),
    ],
)
def test_default_office_both_parts_are_tasks(text: str, got: list[tuple[str, str]]) -> None:
    frame = _DEFAULT(text)
    assert [(t.kind, t.item) for t in frame.tasks] == got, frame


def test_harbour_a_stamp_nobody_can_do_is_asked_before_the_scan() -> None:
    frame = _HARBOUR("I need my document scanned and stamped")
    assert not frame.tasks and frame.question is not None, frame
    assert "stamped" in frame.question and "Shall I still scan" in frame.question


def test_harbour_yes_runs_the_rest_and_no_runs_nothing() -> None:
    said = answered_reader(harbour_office, "may")
    yes = said("I need my document scanned and stamped", ["yes please"])
    assert [(t.kind, t.item) for t in yes.tasks] == [("copy", "document")], yes
    no = said("I need my document scanned and stamped", ["no"])
    assert not no.tasks, no


@pytest.mark.parametrize(
    "text",
    [
        "please stamp my document",  # nothing else asked: declined with the reason
        "I need my document scanned and laminated",  # a document is not laminated here
    ],
)
def test_harbour_a_part_that_cannot_be_done_is_declined_with_why(text: str) -> None:
    frame = _HARBOUR(text)
    assert not frame.tasks and frame.decline is not None, frame


@pytest.mark.parametrize(
    ("text", "got"),
    [
        ("get my document copied and stamped", [("copy", "document"), ("seal", "document")]),
        ("get it stamped and copied", [("seal", "document"), ("copy", "document")]),
        (
            "copy my document and bring me Zhang's stapler",
            [("copy", "document"), ("transfer", "stapler")],
        ),
    ],
)
def test_must_not_change_parts_read_before(text: str, got: list[tuple[str, str]]) -> None:
    frame = _DEFAULT(text)
    assert [(t.kind, t.item) for t in frame.tasks] == got, frame


def test_must_not_change_a_pronoun_with_nothing_to_name_it_is_still_asked() -> None:
    frame = _DEFAULT("get it copied")
    assert not frame.tasks and frame.question is not None, frame
