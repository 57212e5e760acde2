"""A colleague asked to do a facility's work ("get Zhang to make me a copy", "ask Lee to print
my file") does it only if they keep a facility that runs it; else it is asked ("Zhang Wei
doesn't run the printer ... Shall I get it done at the printer instead?"), a yes doing the
request without the named doer (``screen.asked_doer``). A person's own work ("get Zhang to
sign my document") and an errand ("ask Zhang to bring me his stapler") are read as before."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of

from assistantx.core.office import Office
from helpers.dataset_offices import default_office_that_sends_out
from helpers.reading import frame_reader


@pytest.mark.parametrize(
    ("text", "who", "facility", "task"),
    [
        (
            "could you get Zhang to make me a copy",
            "Zhang Wei",
            "printer",
            ("copy", "document", "wang", "wang"),
        ),
        ("ask Lee to print my file", "Lee Ming", "printer", ("print", "file", "wang", "wang")),
        (
            "have Zhang copy my document",
            "Zhang Wei",
            "printer",
            ("copy", "document", "wang", "wang"),
        ),
        (
            "please ask Lee to print my file for Gao",
            "Lee Ming",
            "printer",
            ("print", "file", "wang", "gao"),
        ),
    ],
)
def test_one_who_does_not_run_it_is_asked_about(
    text: str, who: str, facility: str, task: tuple[str, str, str, str]
) -> None:
    p = parser("default")
    frame = p.parse(text, "wang")
    assert frame.tasks == [] and frame.question is not None, frame
    assert who in frame.question and f"the {facility} instead?" in frame.question
    yes = p.parse_with_answers(text, "wang", ["yes"])
    assert [(t.kind, t.item, t.owner, t.recipient) for t in yes.tasks] == [task]
    assert p.parse_with_answers(text, "wang", ["no"]).tasks == []


def test_harbour_scan_by_one_who_does_not_keep_the_scanner() -> None:
    frame = parser("harbour").parse("could you get Will to scan my document", "may")
    assert frame.tasks == [] and frame.question is not None
    assert "Will Tanaka doesn't run the scanner" in frame.question


@pytest.mark.parametrize(
    ("office", "who", "text", "tasks"),
    [
        # they keep the facility: the work is done
        (
            "default",
            "wang",
            "could you get Xu to make me a copy",
            [("copy", "document", "wang", "wang")],
        ),
        ("default", "wang", "ask Mao to print my file", [("print", "file", "wang", "wang")]),
        (
            "harbour",
            "may",
            "could you get Mark to scan my document",
            [("copy", "document", "may", "may")],
        ),
        # a person's own work, and an errand: not a facility's
        (
            "default",
            "wang",
            "ask Zhang to bring me his stapler",
            [("transfer", "stapler", "zhang", "wang")],
        ),
    ],
)
def test_must_not_change(
    office: str, who: str, text: str, tasks: list[tuple[str, str, str, str]]
) -> None:
    assert tasks_of(office, text, who) == tasks


def test_a_signature_asked_of_a_colleague_is_theirs() -> None:
    frame = parser("default").parse("get Zhang to sign my document", "wang")
    assert [(t.kind, t.actor) for t in frame.tasks] == [("sign", "zhang")]


def _couriers() -> Office:
    return default_office_that_sends_out("courier", "courier", "send off", "the address")


_courier_frame = frame_reader(_couriers, "wang")


def test_a_verb_with_a_particle_is_asked_only_whole() -> None:
    # round 207 (read): "send" of a courier's "send off" made "get Ravi to send me his rough
    # mix" a courier run by someone who does not keep the courier desk; it is his file
    frame = _courier_frame("could you get Zhang to send me his file")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("send_file", "file", "zhang", "wang")
    ], frame


@pytest.mark.parametrize(
    "text", ["ask Zhang to send off my document", "ask Zhang to send my document off"]
)
def test_the_whole_verb_is_still_the_facilitys_work(text: str) -> None:
    frame = _courier_frame(text)
    assert frame.question is not None and "doesn't run the printer" in frame.question, frame
