"""A colleague's one-word name that is also an article or a title ("An" of Trần Văn An) is a
name in the lexicon, keyed by its own word, never by the empty key of nothing said; it names
the colleague in a clear name slot (capitalised inside a sentence, or after "to", "for",
"from" with nothing an article would open after it), and stays the article elsewhere."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import HARBOUR_FILE
from helpers.yaml_files import raw_yaml


@functools.cache
def _office() -> Office:
    """Harbour where Mark is Trần Văn An, called An."""
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    for p in raw["people"]:
        if p["id"] == "mark":
            p["name"], p["aliases"] = "Trần Văn An", ["An"]
    return parse_office(raw, "harbour with An")


@functools.cache
def _parser() -> InstructionParser:
    return InstructionParser(_office())


def _tasks(text: str) -> list[tuple[str, str | None, str | None, str]]:
    frame = _parser().parse(text, "may")
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


def test_no_empty_name_in_the_lexicon() -> None:
    lex = Lexicon.from_office(_office())
    assert "" not in lex.name_words and "" not in lex.people
    assert lex.name_words["an"] == {"mark"}


@pytest.mark.parametrize(
    "text",
    [
        "take my tape to An",
        "give An my tape",
        "bring my tape to An please",
        "could you take my tape dispenser to An",
    ],
)
def test_an_is_the_colleague(text: str) -> None:
    assert _tasks(text) == [("transfer", "tape", "may", "mark")]


def test_ans_thing() -> None:
    assert _tasks("bring me An's ruler") == [("transfer", "ruler", "mark", "may")]


@pytest.mark.parametrize(
    "text",
    [
        "take my tape to an office",  # the article before a noun: nobody named
        "can I have an eraser",
    ],
)
def test_the_article_stays_an_article(text: str) -> None:
    frame = _parser().parse(text, "may")
    assert all(t.recipient != "mark" for t in frame.tasks), frame
