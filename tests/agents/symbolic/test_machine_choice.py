"""A thing at hand put through a machine of several services, none of them said: "put this
through the printer" where the printer prints files and copies papers asks which, in one
short question naming both ("Print your file, or copy your document?"), not the generic
"what do you need?"; the answer ("copy", "the file", "photocopy") is that service on the
requester's own thing. A machine named by one service's doer noun ("the copier"), a verb of
a service said, or the thing named ("my file") is read as before."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import HARBOUR_FILE, default_office
from helpers.reading import answered_reader, frame_reader, parser_for
from helpers.yaml_files import raw_yaml

_DEFAULT = frame_reader(default_office, "lee")
_ANSWERED = answered_reader(default_office, "lee")


@functools.cache
def _harbour_with_a_multifunction_scanner() -> Office:
    """The harbour office whose scanner also prints files, also called "the office machine"
    (a name of neither service: "the scanner" itself picks its scan)."""
    raw = raw_yaml(HARBOUR_FILE)
    for facility in raw["facilities"]:
        if facility["id"] == "scanner":
            facility["operations"] = [*facility["operations"], "print"]
            facility["synonyms"] = [*facility.get("synonyms", []), "office machine"]
    return parse_office(raw)


@pytest.mark.parametrize(
    "text",
    [
        "put this through the printer",
        "can this go through the printing machine?",
        "run it through the printer please",
    ],
)
def test_default_office_asks_which_service_naming_both(text: str) -> None:
    frame = _DEFAULT(text)
    assert not frame.tasks and frame.question == "Print your file, or copy your document?"


def test_an_office_built_with_another_two_service_machine_asks_the_same() -> None:
    frame = parser_for(_harbour_with_a_multifunction_scanner).parse(
        "put this through the office machine", "may"
    )
    assert not frame.tasks and frame.question == "Scan your document, or print your file?"


@pytest.mark.parametrize(
    ("answer", "kind", "item"),
    [
        ("copy", "copy", "document"),
        ("photocopy it please", "copy", "document"),
        ("the document", "copy", "document"),
        ("Print it", "print", "file"),
        ("my file", "print", "file"),
    ],
)
def test_the_answer_picks_the_service(answer: str, kind: str, item: str) -> None:
    frame = _ANSWERED("put this through the printer", [answer])
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [(kind, item, "lee", "lee")], frame


def test_the_answer_keeps_whom_it_is_for() -> None:
    frame = _ANSWERED("run this through the printer for Zhang", ["copy it"])
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("copy", "zhang")], frame


@pytest.mark.parametrize("answer", ["both", "not sure"])
def test_an_answer_naming_neither_or_both_is_asked_again(answer: str) -> None:
    frame = _ANSWERED("put this through the printer", [answer])
    assert not frame.tasks, frame


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        ("put this through the copier", "copy", "document"),  # the copier: its copy
        ("run my file through the printer", "print", "file"),  # the file: its print
        ("copy this through the printer", "copy", "document"),  # the verb said
    ],
)
def test_must_not_change_a_service_said_is_done(text: str, kind: str, item: str) -> None:
    frame = _DEFAULT(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [(kind, item)], frame


def test_must_not_change_the_machine_named_by_one_service_picks_it() -> None:
    frame = parser_for(_harbour_with_a_multifunction_scanner).parse(
        "put this through the scanner", "may"
    )
    assert [(t.kind, t.item) for t in frame.tasks] == [("copy", "document")], frame


def test_must_not_change_a_question_about_the_machine_moves_nothing() -> None:
    frame = InstructionParser(default_office()).parse("has this gone through the printer?", "lee")
    assert not frame.tasks and frame.question != "Print your file, or copy your document?"
