"""A word said of an item, not an item of its own: "anyone got a torque wrench *going spare*?"
where the office also calls its spare key a "spare". One word that is also an adjective,
right after another item or after a verb that says a state ("going", "is", "lying"), tells
the state of the thing before it; read as a second item it made the request ask about keys."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import language

# "going spare", "is spare", "lying spare": the verbs a state is said with
_DESCRIBING = frozenset({"going", "is", "are", "lying", "sitting", "kicking"})


def said_of_item(tokens: Sequence[Token], mentions: Sequence[Mention], n: int) -> bool:
    """Whether item mention ``n`` only says the state of the item mentioned before it."""
    m = mentions[n]
    if m.kind != "item" or m.end - m.start != 1 or m.possessive:
        return False
    earlier = [k for k in mentions[:n] if k.kind == "item"]
    if not earlier:
        return False
    before = tokens[m.start - 1].word if m.start else ""
    if earlier[-1].end != m.start and before not in _DESCRIBING:
        return False
    if before in _DESCRIBING and earlier[-1].end != m.start - 1:
        return False  # "the stapler is here, a spare too": not right after the thing
    if earlier[-1].end == m.start and _subject_of_a_verb(tokens, m.end):
        return False  # "my poster proof needs the stamp": the compound's head, a thing
    return "ADJ" in language.lemmas(tokens[m.start].word)


def without_states(tokens: Sequence[Token], mentions: Sequence[Mention]) -> list[Mention]:
    """``mentions`` with each item that only says a state read as a plain word."""
    return [
        Mention("word", m.start, m.end, (tokens[m.start].word,), m.possessive, m.text)
        if said_of_item(tokens, mentions, n)
        else m
        for n, m in enumerate(mentions)
    ]


def _subject_of_a_verb(tokens: Sequence[Token], at: int) -> bool:
    """Whether a finite verb follows at ``at`` in the same clause: the words before it are
    its subject's noun phrase, whose last noun is the thing ("poster *proof* needs")."""
    if at >= len(tokens) or tokens[at].after_pause or tokens[at].opens:
        return False
    return language.is_finite_verb(tokens[at].word)
