"""A file-type word of the office names the file sent: where the office keeps an electronic
type of its own beside the generic file (a slide deck, a spreadsheet), "send Mark my slides"
forwards the requester's slide deck, not their generic file (``_kinds`` reads the type the
words named; ``Office.file_of`` gives that type's item). The generic file's own words still
send the generic file."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from assistantx.evaluation import metrics
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.one_episode import ppdr_episode
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml

_OWN_TYPES = (
    {"id": "slides", "name": "slide deck", "synonyms": ["slides", "deck", "presentation"]},
    {"id": "sheet", "name": "spreadsheet file", "synonyms": ["spreadsheet", "workbook", "xls"]},
)


def _with_own_file_types(path: Any) -> Office:
    """The office at ``path`` with a slide deck and a spreadsheet as electronic types of
    their own (their words taken off the generic file), owned by everyone who has a file."""
    raw: dict[str, Any] = raw_yaml(path)
    taken = {w for t in _OWN_TYPES for w in t["synonyms"]}
    files = next(t for t in raw["item_types"] if t["id"] == "file")
    files["synonyms"] = [w for w in files["synonyms"] if w not in taken]
    raw["item_types"] += [{"kind": "electronic", **t} for t in _OWN_TYPES]
    for person in raw["people"]:
        if any(o["type"] == "file" for o in person["owns"]):
            person["owns"] += [{"type": t["id"], "known": True} for t in _OWN_TYPES]
    return parse_office(raw)


harbour_with_decks = functools.cache(lambda: _with_own_file_types(HARBOUR_FILE))
default_with_decks = functools.cache(lambda: _with_own_file_types(DEFAULT_FILE))

_HARBOUR = frame_reader(harbour_with_decks, "will")
_DEFAULT = frame_reader(default_with_decks, "lin")

Sent = tuple[str | None, str | None, str]  # item, owner, recipient


def _sent(frame: object) -> list[Sent]:
    return [
        (t.item, t.owner, t.recipient) for t in getattr(frame, "tasks", []) if t.kind == "send_file"
    ]


@pytest.mark.parametrize(
    ("text", "sent"),
    [
        ("print my report and send Mark my slides too", [("slides", "will", "mark")]),
        ("email Rose my spreadsheet", [("sheet", "will", "rose")]),
        ("forward my workbook to Mark pls", [("sheet", "will", "mark")]),
        ("print my document and email Rose my presentation as well", [("slides", "will", "rose")]),
        ("send Rose Mark's deck", [("slides", "mark", "rose")]),
        # the neighbour: the generic file's own word is the generic file
        ("send Mark my file", [("file", "will", "mark")]),
        ("email Rose my pdf", [("file", "will", "rose")]),
    ],
)
def test_harbour_the_named_type_is_sent(text: str, sent: list[Sent]) -> None:
    frame = _HARBOUR(text)
    assert frame.question is None, frame
    assert _sent(frame) == sent, frame


@pytest.mark.parametrize(
    ("text", "sent"),
    [
        ("email Wang my spreadsheet", [("sheet", "lin", "wang")]),
        ("copy my contract and send Zhang my slides too", [("slides", "lin", "zhang")]),
        ("send Zhang my file", [("file", "lin", "zhang")]),
    ],
)
def test_default_the_named_type_is_sent(text: str, sent: list[Sent]) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _sent(frame) == sent, frame


def test_office_file_of_a_named_type() -> None:
    office = harbour_with_decks()
    assert office.file_of("will", "slides") == "slides:will"
    assert office.file_of("will") == "file:will"
    assert office.file_of("will", "document") == "file:will"  # no electronic type: the file


@pytest.mark.parametrize(
    ("who", "text", "received"),
    [
        ("will", "email Rose my spreadsheet", ["rose", "sheet:will"]),
        ("will", "send Mark my slides", ["mark", "slides:will"]),
        ("will", "send Rose Mark's deck", ["rose", "slides:mark"]),
    ],
)
async def test_the_named_file_arrives(who: str, text: str, received: list[str]) -> None:
    episode = await ppdr_episode(harbour_with_decks(), who, text, [{"received": received}])
    assert metrics.success(episode), (episode.milestones, episode.trace.summary)
    assert metrics.wrong_handovers(episode) == []
