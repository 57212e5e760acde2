"""After the frames: a thing no one in the office has is declined in words, not asked again."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.unknown_items import unknown_item
from assistantx.core.office import Office


@pytest.fixture(scope="module")
def terms(office: Office) -> Terms:
    return Terms(office, Lexicon.from_office(office))


def unknown(terms: Terms, text: str) -> str | None:
    lexed = terms.lex.read(text)
    return unknown_item(terms, lexed.tokens, lexed.mentions)


def test_a_thing_no_one_has_is_said_so_with_what_the_office_offers(terms: Terms) -> None:
    said = unknown(terms, "bring me a tape measure")
    assert said is not None
    assert said.startswith("Sorry, there is no tape measure in this office that I know of")
    assert "What I can do here:" in said


def test_the_thing_ends_where_a_reason_starts(terms: Terms) -> None:
    said = unknown(terms, "bring me a power bank as my phone is dying")
    assert said is not None and said.startswith("Sorry, there is no power bank in")


@pytest.mark.parametrize(
    "text",
    [
        "bring me a stapler",  # the office has it
        "bring me a few",  # how many of what: asked, not declined
        "print my file",  # no fetch
    ],
)
def test_what_is_no_unknown_thing(terms: Terms, text: str) -> None:
    assert unknown(terms, text) is None
