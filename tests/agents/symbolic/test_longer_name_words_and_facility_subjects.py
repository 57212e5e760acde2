"""Two follow-ups of this round's mechanisms, on shapes the first tests did not build:
- a paper noun that is only a word of one of the office's longer names ("log" where the paper
  is called a "delegation log") still heads a topic compound: "copy the sample log" is the
  requester's paper, also when the thing before it is named in the plural ("samples");
- a facility's one-word name is a clause's subject like a service's word: "van leaves at 3"
  beside a signing request (the van being the courier's) is context, not a courier job."""

from __future__ import annotations

import functools
from collections.abc import Sequence
from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from assistantx.core.task_schema import Task
from helpers.dataset_offices import DEFAULT_FILE
from helpers.library_courier import library_courier
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml

Row = tuple[str, str | None, str | None, str]


def _rows(tasks: Sequence[Task]) -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in tasks]


@functools.cache
def _trials_unit() -> Office:
    """The default office as a trials unit's: its paper is also a "delegation log" (never a
    bare "log"), its samples are named in the plural."""
    raw: dict[str, Any] = raw_yaml(DEFAULT_FILE)
    for t in raw["item_types"]:
        if t["id"] == "document":
            t["synonyms"] = [*t.get("synonyms", []), "delegation log"]
    raw["item_types"].append(
        {"id": "samples", "name": "samples", "synonyms": ["sample rack", "tubes"]}
    )
    return parse_office(raw, "default as a trials unit")


_trials = frame_reader(_trials_unit, "lin")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("copy the sample log and give the copy to Wang", [("copy", "document", "lin", "wang")]),
        ("copy the sample log", [("copy", "document", "lin", "lin")]),
        ("copy the tube log for Zhang", [("copy", "document", "lin", "zhang")]),
        # must not change: the longer name is the paper; the samples said alone are the thing
        ("copy my delegation log for Wang", [("copy", "document", "lin", "wang")]),
        ("bring me Wang's samples", [("transfer", "samples", "wang", "lin")]),
    ],
)
def test_a_word_of_a_longer_paper_name_heads_a_topic_compound(
    text: str, expected: list[Row]
) -> None:
    assert _rows(_trials(text).tasks) == expected


@functools.cache
def _library_with_a_van() -> Office:
    """The library courier office whose courier desk is also called "the van"."""
    office = library_courier()
    raw = office.model_dump(mode="json")
    for f in raw["facilities"]:
        if f["id"] == "courier_desk":
            f["synonyms"] = [*f.get("synonyms", []), "van", "the van"]
    return parse_office(raw, "library with a van")


_library = frame_reader(_library_with_a_van, "lin")


@pytest.mark.parametrize(
    "text",
    [
        "can you get my document signed by Wang? van leaves at 3",
        "can you get my document signed by Wang? the van leaves at 3",
        "can you get my document signed by Wang, van goes at noon",
    ],
)
def test_a_facility_word_before_its_verb_is_the_subject(text: str) -> None:
    frame = _library(text)
    assert _rows(frame.tasks) == [("sign", "document", "lin", "lin")], frame.question
    assert frame.decline is None


def test_the_facility_word_as_a_command_is_still_its_service() -> None:
    """Must not change: "courier my book to Westgate branch" is a send-out."""
    frame = _library("courier my book to Westgate branch")
    assert [t.kind for t in frame.tasks] == ["courier"] or frame.tasks[0].operation == "courier"
