"""The screen's parts on the default office: its terms, and a message cut into lexed pieces."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.screen.english import split_words
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, pieces
from assistantx.agents.symbolic.reading.screen.rules import Rule
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech_acts import acts_reader
from assistantx.core.office import Office
from reading.screen._judge import Judge, Read


@pytest.fixture(scope="module")
def terms(office: Office) -> Terms:
    return Terms(office, Lexicon.from_office(office))


@pytest.fixture(scope="module")
def message(terms: Terms) -> Read:
    """A message as the screen walks it: its pieces, each read by the office's lexicon and
    the speech acts."""

    def read(text: str) -> Message:
        acts = acts_reader(terms.acts, terms.self_words, split_words(text))
        read = terms.lex.read
        return Message(text=text, pieces=pieces(text, read, acts), lexed=read(text))

    return read


@pytest.fixture(scope="module")
def judged(terms: Terms, message: Read) -> Judge:
    """What one rule finds in the first piece of a message said by ``requester``."""

    def judge(rule: Rule, text: str, requester: str) -> Finding | None:
        msg = message(text)
        return rule(terms, msg, msg.pieces[0], requester)

    return judge
