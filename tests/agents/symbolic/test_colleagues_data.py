"""A colleague's possessive before a noun of what an instrument or a computer records ("need
Frank's plate reader data, can u get it off him", "can you get me Bill's survey results", "I
need his gel images") is that colleague's electronic file, forwarded to the requester, where
the office has a file type (blind rounds 43-48's class: "I'm not sure what you mean by
'...'s plate'"). Where the office has none, or the noun is a word of one of its own items
("data cable"), it is asked about as before."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import load_office, parse_office
from helpers.reading import frame_reader
from helpers.word_names import raw_word_names, word_names

_frame = frame_reader(word_names, "petra")


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("need Frank's plate reader data, can u get it off him", "frank"),
        ("can you get me Bill's survey results", "bill"),
        ("can you get me Frank's data", "frank"),
        ("I need Grant's spreadsheet", "grant"),
        ("Frank ran the gels yesterday, I need his gel images", "frank"),
        ("could you grab Rich's sales numbers for me", "rich"),
    ],
)
def test_a_colleagues_data_is_their_file(text: str, owner: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("send_file", "file", owner, "petra")
    ], frame


def _without_files() -> Any:
    raw = raw_word_names()
    raw["item_types"] = [t for t in raw["item_types"] if t.get("kind") != "electronic"]
    for p in raw["people"]:
        p["owns"] = [o for o in p["owns"] if o["type"] != "file"]
    return parse_office(raw, raw["name"])


@pytest.mark.parametrize(
    "text", ["need Frank's plate reader data, can u get it off him", "get me Bill's survey results"]
)
def test_without_a_file_type_it_stays_a_question(text: str) -> None:
    frame = frame_reader(_without_files, "petra")(text)
    assert frame.tasks == [] and frame.question is not None, frame


def test_a_word_of_the_offices_own_items_is_read_as_before() -> None:
    office = load_office()
    frame = frame_reader(lambda: office, "lee")("can you get me Zhang's data cable")
    assert [(t.item, t.owner) for t in frame.tasks] == [("data_cable", "zhang")], frame
    frame = frame_reader(lambda: office, "lee")("need Wang's plate reader data, can u get it")
    assert frame.tasks == [], frame
