"""A thing taken to a colleague "in" the place of a facility that makes something from it is a
hand-over to that colleague, where they are: "take my camera card to Frank in the edit"
(a blind round's newsroom, where "the edit" names the ingest desk Frank keeps) ran the
ingest and sent the rushes to Frank. The facility word after "in" said after a person is
where the person is, as the treating and rendering facilities already read it
(``_kinds.persons_place``); "put my card in the edit" still asks for its work."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers.kit_room import raw_kit_room


@functools.cache
def _parser() -> InstructionParser:
    raw = raw_kit_room()
    for facility in raw["facilities"]:
        if facility["id"] == "ingest_desk":
            facility["synonyms"] = ["edit", "the edit"]
    for operation in raw["operations"]:
        if operation["id"] == "ingest":
            operation["product"] = "spreadsheet"  # the rushes come back as a file
    return InstructionParser(parse_office(raw, "kit room with the edit"))


@pytest.mark.parametrize(
    "text",
    [
        "take my camera card to Frank in the edit",
        "bring my memory card to Frank in the edit pls",
    ],
)
def test_a_colleague_in_the_place_gets_the_thing(text: str) -> None:
    frame = _parser().parse(text, "ana")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "camera_card", "ana", "frank")
    ], frame


def test_must_not_change_the_thing_put_in_the_place_asks_for_its_work() -> None:
    frame = _parser().parse("put my camera card in the edit", "ana")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("copy", "ana")], frame
