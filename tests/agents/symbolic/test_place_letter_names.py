"""A place whose name ends in a letter or a number ("Studio A", "Lab B", "Room 3") is read
whole: its last word is no article (``Lexicon._place_letter_at``), so a request that ends on
it is no message cut off after "a"."""

from __future__ import annotations

import copy
import functools
from typing import Any

import pytest
import yaml

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE

_ROOMS = [("studio_a", "Studio A"), ("lab_b", "Lab B"), ("room_3", "Room 3")]


@functools.cache
def _parser(base: str) -> InstructionParser:
    source = HARBOUR_FILE if base == "harbour" else DEFAULT_FILE
    raw: dict[str, Any] = copy.deepcopy(yaml.safe_load(source.read_text(encoding="utf-8")))
    for n, (room_id, name) in enumerate(_ROOMS):
        raw["locations"].append(
            {"id": room_id, "kind": "room", "name": name, "x": 5.0 + 4 * n, "y": 16.0}
        )
    office: Office = parse_office(raw, f"{base} with lettered rooms")
    return InstructionParser(office)


@pytest.mark.parametrize(
    ("base", "requester", "text", "item", "recipient"),
    [
        ("harbour", "mark", "bring my ruler to Pat in Studio A", "ruler", "pat"),
        ("harbour", "mark", "take my ruler to Joy in Lab B", "ruler", "joy"),
        ("harbour", "mark", "take my ruler to Joy in Studio A please", "ruler", "joy"),
        ("default", "mao", "bring my seal to Wang in Studio A", "seal", "wang"),
        ("default", "mao", "bring my seal to Wang in Room 3", "seal", "wang"),
    ],
)
def test_a_place_ending_in_a_letter_is_read_whole(
    base: str, requester: str, text: str, item: str, recipient: str
) -> None:
    frame = _parser(base).parse(text, requester)
    assert frame.question is None, frame.question
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, recipient)]


@pytest.mark.parametrize("base", ["harbour", "default"])
def test_the_place_is_one_mention(base: str) -> None:
    lex = _parser(base).lex
    lexed = lex.read("meet me in Studio A")
    places = [m for m in lexed.mentions if m.kind == "place"]
    assert [(m.ids, m.end - m.start) for m in places] == [(("studio_a",), 2)]


def test_a_message_cut_off_after_an_article_is_still_asked() -> None:
    # must not change: "a" that ends no place's name is the article, left hanging
    frame = _parser("harbour").parse("take my ruler to Pat in a", "mark")
    assert frame.question is not None and "cut off" in frame.question


def test_an_article_after_a_place_word_stays_an_article() -> None:
    # must not change: "the studio a bit later": lowercase, something after it
    lexed = _parser("harbour").lex.read("take my ruler to the studio a bit later")
    assert not any(m.kind == "place" and m.end - m.start == 2 for m in lexed.mentions)
