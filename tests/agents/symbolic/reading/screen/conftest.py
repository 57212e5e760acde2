"""The screen's parts on the default office: its terms, and a message cut into lexed pieces."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.screen.pieces import Message, pieces
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core.office import Office


@pytest.fixture(scope="module")
def terms(office: Office) -> Terms:
    return Terms(office, Lexicon.from_office(office))


@pytest.fixture(scope="module")
def message(terms: Terms) -> Callable[[str], Message]:
    """A message as the screen walks it: its pieces, each read by the office's lexicon."""

    def read(text: str) -> Message:
        return Message(text=text, pieces=pieces(text, terms.lex.read))

    return read
