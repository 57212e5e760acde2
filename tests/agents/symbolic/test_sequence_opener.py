"""A word of sequence opening a clause ("..., then have Wang sign my contract") joins it to the
clause before, as "and" does: "have/get/ask X (to) <verb>" after it is a second request, never
a statement told (``reading.sequence_opener``); "then I'll have Wang sign it" stays the
speaker's own plan."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import load_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE


@functools.cache
def _parser(base: str) -> InstructionParser:
    return InstructionParser(load_office(HARBOUR_FILE if base == "harbour" else DEFAULT_FILE))


def _read(base: str, requester: str, text: str) -> list[tuple[str, str | None, str]]:
    frame = _parser(base).parse(text, requester)
    assert frame.question is None, frame.question
    return [(t.kind, t.actor, t.item) for t in frame.tasks]


@pytest.mark.parametrize(
    ("base", "requester", "text", "tasks"),
    [
        (
            "default",
            "lin",
            "Print my file, then have Wang sign my contract",
            [("print", None, "file"), ("sign", "wang", "document")],
        ),
        (
            "default",
            "lin",
            "print my report and have Zhang sign my contract",
            [("print", None, "file"), ("sign", "zhang", "document")],
        ),
        (
            "default",
            "lin",
            "Print my file. Then have Zhang stamp my document",
            [("print", None, "file"), ("seal", "zhang", "document")],
        ),
        (
            "default",
            "lin",
            "print my file, and then have Wang sign my contract",
            [("print", None, "file"), ("sign", "wang", "document")],
        ),
        (
            "default",
            "lin",
            "print my file, afterwards have Wang sign my contract",
            [("print", None, "file"), ("sign", "wang", "document")],
        ),
        (
            "harbour",
            "will",
            "print my file, then have Joy sign my document",
            [("print", None, "file"), ("sign", "joy", "document")],
        ),
    ],
)
def test_have_someone_work_after_then_is_a_second_request(
    base: str, requester: str, text: str, tasks: list[tuple[str, str | None, str]]
) -> None:
    assert _read(base, requester, text) == tasks


@pytest.mark.parametrize(
    ("base", "requester", "text"),
    [
        ("default", "lin", "Print my file, then I'll have Wang sign it"),
        ("harbour", "will", "scan my document, then I'll have Joy sign it"),
    ],
)
def test_the_speakers_own_plan_after_then_is_told(base: str, requester: str, text: str) -> None:
    # must not change: "I'll have Wang sign it" is what the speaker will do; only the first
    tasks = _read(base, requester, text)
    assert len(tasks) == 1
    assert tasks[0][0] in ("print", "copy")


def test_a_fault_told_after_then_is_still_told() -> None:
    # must not change: "then the stapler broke" is news, nothing is fetched or mended
    assert _read("default", "lin", "print my file, then the stapler broke") == [
        ("print", None, "file")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "I'd like a copy of my contract, and then the original signed by Wang",
        "a copy of my contract please, then the original signed by Zhang",
    ],
)
def test_a_wanted_state_after_then_is_not_told(text: str) -> None:
    # found by blind round 136 after this rule: "and then the original signed by Dr D'Souza"
    # (no verb of its own: the work wanted on it) was dropped as a statement, and only the
    # copy made; it is asked about, as before the rule, never silently left out
    frame = _parser("default").parse(text, "lin")
    assert not any(e.meaning == "a statement, context only" for e in frame.evidence), frame
    assert frame.question is not None or any(t.kind == "sign" for t in frame.tasks), frame


def test_a_passive_told_after_then_is_still_told() -> None:
    # must not change: "then it was signed by Wang" says it happened
    assert _read("default", "lin", "print my file, then it was signed by Wang") == [
        ("print", None, "file")
    ]
