"""The plural of a name "N of M" is made on its head N ("bills of lading", "letters of
credit", "pairs of scissors"): the reader knows the office's thing by that plural too, in a
small office built here on the default and on harbour (issue #23)."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core import language
from assistantx.core.office import parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.yaml_files import raw_yaml

_PAPERS = [
    {"id": "lading", "name": "bill of lading", "synonyms": ["B/L"], "kind": "personal"},
    {"id": "origin_cert", "name": "certificate of origin", "kind": "personal"},
    {"id": "credit_letter", "name": "letter of credit", "kind": "personal"},
]


def _parser(base: str, owner: str) -> InstructionParser:
    raw: dict[str, Any] = raw_yaml(DEFAULT_FILE if base == "default" else HARBOUR_FILE)
    raw["item_types"] += [dict(t) for t in _PAPERS]
    for p in raw["people"]:
        if p["id"] == owner:
            p["owns"] = [*p.get("owns", []), *({"type": t["id"], "known": True} for t in _PAPERS)]
    return InstructionParser(parse_office(raw, f"{base} with trade papers"))


def _tasks(base: str, owner: str, text: str, requester: str) -> list[tuple[str, str | None]]:
    frame = _parser(base, owner).parse(text, requester)
    return [(t.item or "", t.owner) for t in frame.tasks]


@pytest.mark.parametrize(
    ("phrase", "plural"),
    [
        ("bill of lading", "bills of lading"),
        ("certificate of origin", "certificates of origin"),
        ("pair of scissors", "pairs of scissors"),
        ("proof of delivery", "proofs of delivery"),
        ("stapler", ""),  # no "of": the ordinary plural is made elsewhere
    ],
)
def test_head_plural(phrase: str, plural: str) -> None:
    assert language.head_plural(phrase) == plural


@pytest.mark.parametrize(
    ("base", "owner", "requester", "text", "item"),
    [
        ("default", "chen", "lee", "bring me Chen's bills of lading", "lading"),
        ("default", "chen", "lee", "bring me Chen's letters of credit", "credit_letter"),
        ("default", "chen", "lee", "can I borrow Chen's certificates of origin", "origin_cert"),
        ("harbour", "grace", "may", "I need the letters of credit from Grace", "credit_letter"),
        ("harbour", "grace", "may", "can I borrow Grace's certificates of origin", "origin_cert"),
    ],
)
def test_plural_of_an_of_name_is_the_thing(
    base: str, owner: str, requester: str, text: str, item: str
) -> None:
    assert _tasks(base, owner, text, requester) == [(item, owner)]


def test_default_pairs_of_scissors_are_scissors() -> None:
    frame = _parser("default", "chen").parse("I need two pairs of scissors", "lee")
    assert [t.item for t in frame.tasks] == ["scissors"]


def test_a_plain_letter_stays_a_document() -> None:
    # must not change: "letter" alone is harbour's document, not the letter of credit
    assert _tasks("harbour", "grace", "bring me Grace's letter", "may") == [("document", "grace")]
