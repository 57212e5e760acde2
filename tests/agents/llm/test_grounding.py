"""A model's reading is grounded only in the requester's own words, matched tolerantly."""

from __future__ import annotations

import pytest

from assistantx.agents.llm.grounding import RequestWords, fold, singular, ungrounded
from assistantx.agents.symbolic.reading.parser import InstructionParser
from assistantx.core.office import DEFAULT_OFFICE, Office, load_office
from assistantx.core.task_schema import TaskKind
from assistantx.evaluation.dataset.tasks import load_tasks


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


GROUNDED: list[tuple[str, TaskKind, str, tuple[str | None, ...]]] = [
    ("print my report and bring it to me", "print", "file", ("lee", "lee")),
    ("make me a coffee", "produce", "coffee", (None, "lee")),
    ("warm up my lunch", "heat", "lunch", ("lee", "lee")),
    ("photocopies of my contract please", "copy", "document", ("lee", "lee")),
    ("bring me ZHĀNG's staplers", "transfer", "stapler", ("zhang", "lee")),
    ("bring me Dr. Zhang Wei's stapeler", "transfer", "stapler", ("zhang", "lee")),
    ("get me the usb cable from wang", "transfer", "data_cable", ("wang", "lee")),
    ("Professor Zhang should sign my contract", "sign", "document", ("lee", "lee", "zhang")),
]


@pytest.mark.parametrize(("text", "kind", "item", "people"), GROUNDED)
def test_what_the_requester_said_is_grounded(
    office: Office, text: str, kind: TaskKind, item: str, people: tuple[str | None, ...]
) -> None:
    assert ungrounded(RequestWords(office, [text]), "lee", kind, item, people) is None


UNGROUNDED: list[tuple[str, TaskKind, str, tuple[str | None, ...], str]] = [
    # the prompt's example copied onto another request
    ("print my report and bring it to me", "transfer", "stapler", ("wang", "lee"), "Wang Fang"),
    ("print my report and bring it to me", "transfer", "stapler", (None, "lee"), "'stapler'"),
    ("bring me Zhang's stapler", "transfer", "stapler", ("zheng", "lee"), "Zheng Hui"),
    ("bring me my lunch", "heat", "lunch", ("lee", "lee"), "heat"),
    ("hmm, the thing", "produce", "coffee", (None, "lee"), "produce"),
]


@pytest.mark.parametrize(("text", "kind", "item", "people", "missing"), UNGROUNDED)
def test_what_the_requester_never_said_is_named(
    office: Office,
    text: str,
    kind: TaskKind,
    item: str,
    people: tuple[str | None, ...],
    missing: str,
) -> None:
    reason = ungrounded(RequestWords(office, [text]), "lee", kind, item, people)
    assert reason is not None and missing in reason


def test_the_requesters_answers_count_as_their_words(office: Office) -> None:
    words = RequestWords(office, ["bring me that thing", "the stapler, from Wang"])
    assert ungrounded(words, "lee", "transfer", "stapler", ("wang", "lee")) is None
    # a phrase never spans two texts
    assert not RequestWords(office, ["a coffee", "machine"]).says("coffee machine")


def test_folding_and_plurals() -> None:
    assert fold("Zhāng WÉI") == "zhang wei"
    assert [singular(w) for w in ("copies", "boxes", "staplers", "glass", "bus")] == [
        "copy",
        "box",
        "stapler",
        "glass",
        "bus",
    ]


@pytest.mark.parametrize("office_file", [None, "offices/harbour/office.yaml"])
def test_every_reading_the_embedded_reader_makes_of_the_dataset_is_grounded(
    office_file: str | None,
) -> None:
    """The check never refuses a right reading: the embedded reader's readings of both
    offices' 210 instructions (each item, person and service found in the words)."""
    path = None if office_file is None else DEFAULT_OFFICE.parent / office_file
    office = load_office(path)
    parser = InstructionParser(office)
    tasks = load_tasks((path or DEFAULT_OFFICE).parent / "tasks.jsonl", office)
    refused = []
    for task in tasks:
        words = RequestWords(office, [task.instruction])
        for read in parser.parse(task.instruction, task.requester).tasks:
            parties = (read.owner, read.recipient, read.actor)
            missing = ungrounded(words, task.requester, read.kind, read.item, parties)
            if missing is not None:
                refused.append((task.instruction, missing))
    assert len(tasks) == 210 and refused == []
