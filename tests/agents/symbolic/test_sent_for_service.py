"""A thing sent to a colleague for work the office knows by a verb ("can it go to Wang to be
fixed?", "take my mug to Wang to fix", "send it to Wang for mending") is that work asked of
the colleague, and the thing comes back to the requester unless the message names someone
else (``reading.sent_for_service``); a colleague who keeps no such service is said and asked.
"take my mug to Wang" and "take my fixed mug to Wang" stay plain transfers."""

from __future__ import annotations

import copy
import functools
from typing import Any

import pytest
import yaml

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import load_office, parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.mending_room import mending_room


@functools.cache
def _parser(base: str) -> InstructionParser:
    if base == "mending":
        return InstructionParser(mending_room())
    if base == "harbour":
        return InstructionParser(load_office(HARBOUR_FILE))
    raw: dict[str, Any] = copy.deepcopy(yaml.safe_load(DEFAULT_FILE.read_text(encoding="utf-8")))
    if base == "repair":
        # the default office with a repair bench for cups, its guards two colleagues
        raw["operations"].append(
            {"id": "repair", "name": "repair", "verbs": ["repair", "fix", "mend"], "input": "cup"}
        )
        raw["facilities"].append(
            {
                "id": "repair_bench",
                "name": "repair bench",
                "location": "print_room",
                "operations": ["repair"],
                "guards": ["zhang", "wang"],
            }
        )
        for p in raw["people"]:
            if p["id"] == "lin":
                p["owns"].append({"type": "cup", "known": True})
    return InstructionParser(parse_office(raw, f"{base} office"))


_REQUESTER = {"repair": "lin", "default": "lin", "mending": "rosa", "harbour": "bill"}


def _read(base: str, text: str) -> tuple[list[tuple[str, str | None, str | None, str]], str | None]:
    frame = _parser(base).parse(text, _REQUESTER[base])
    return [(t.kind, t.actor, t.recipient, t.item) for t in frame.tasks], frame.question


@pytest.mark.parametrize(
    ("base", "text", "task"),
    [
        (
            "repair",
            "my mug's cracked, can it go to Wang to be fixed? need it back",
            ("wang", "cup"),
        ),
        ("repair", "take my mug to Wang to fix", ("wang", "cup")),
        ("repair", "send my mug to Zhang for mending", ("zhang", "cup")),
        ("default", "can my contract go to Wang to be signed?", ("wang", "document")),
        ("default", "send my contract to Zhang for stamping", ("zhang", "document")),
        ("harbour", "take my badge to Sue to laminate", ("sue", "badge")),
        ("harbour", "can my badge go to Max to be laminated? need it back", ("max", "badge")),
        ("mending", "send my book over to Nell for repair", ("nell", "book")),
        ("mending", "my book's torn, can it go to Omar to be mended?", ("omar", "book")),
    ],
)
def test_the_colleague_does_the_work_and_the_requester_gets_it_back(
    base: str, text: str, task: tuple[str, str]
) -> None:
    tasks, question = _read(base, text)
    assert question is None, question
    assert len(tasks) == 1
    _, actor, recipient, item = tasks[0]
    assert (actor, item) == task
    assert recipient == _REQUESTER[base]


def test_another_recipient_named_gets_it() -> None:
    tasks, question = _read("mending", "take my book to Nell to fix it and then give it to Ivo")
    assert question is None, question
    assert [(t[1], t[2]) for t in tasks] == [("nell", "ivo")]


@pytest.mark.parametrize(
    ("base", "text", "who"),
    [
        ("mending", "take my book to Lee to fix", "Lee Hart"),
        ("harbour", "take my badge to Joy to laminate", "Joy Achebe"),
    ],
)
def test_a_colleague_who_keeps_no_such_service_is_said_and_asked(
    base: str, text: str, who: str
) -> None:
    tasks, question = _read(base, text)
    assert not tasks
    assert question is not None and question.startswith(f"{who} doesn't look after")


@pytest.mark.parametrize(
    ("base", "text", "who"),
    [
        # must not change: no work said after the name, the thing goes to the colleague
        ("repair", "take my mug to Wang", "wang"),
        ("repair", "take my fixed mug to Wang", "wang"),
        ("harbour", "take my badge to Sue", "sue"),
        ("mending", "take my book to Nell to read", "nell"),  # reading is no work of ours
    ],
)
def test_a_plain_transfer_stays_one(base: str, text: str, who: str) -> None:
    tasks, question = _read(base, text)
    assert question is None, question
    assert [(t[0], t[2]) for t in tasks] == [("transfer", who)]
