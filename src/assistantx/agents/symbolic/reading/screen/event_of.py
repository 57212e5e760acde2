"""A thing of an event beside a request: "Would you mind fetching Wang's stapler for me? Need
a copy of the new signing at the desk". After "of" and a determiner, an office verb's "-ing"
form is a noun naming an occasion ("the new signing", "the printing"), never a paper of the
office to work on; the clause names no item there, so it says why the request is made (the
speaker's own want), and reading it as a task asked what to do with a photocopy. A clause
whose "of" names a thing of the office ("a copy of my contract") or a paper the "-ing" word
only modifies ("a copy of the printing schedule") is read as before, and so is a clause alone
(it may be the request itself)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import DETERMINERS
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import language

_MOST_BETWEEN = 2  # the words between the determiner and the "-ing" noun ("the new")


def event_of(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    del requester  # whose request it is changes nothing here
    if piece.acts.imperative or piece.acts.question is not None or piece.asks:
        return None
    if not any(p.acts.request for p in msg.pieces if p is not piece):
        return None  # alone it may be the request itself: read on
    words = content(piece.words)
    if "of" not in words:
        return None
    after = words[words.index("of") + 1 :]
    if not after or after[0] not in DETERMINERS:
        return None
    if any(m.kind == "item" for m in piece.lexed.mentions if _after_of(piece, m.start)):
        return None  # "a copy of my contract": a thing of the office, asked
    for n, word in enumerate(after[1 : 2 + _MOST_BETWEEN], start=1):
        if word.endswith("ing") and _office_verbs_gerund(terms, word) and _heads(after, n):
            return Finding("statement", piece, "a thing of an occasion, why it is asked")
    return None


def _heads(words: list[str], n: int) -> bool:
    """Whether ``words[n]`` ends its noun phrase (nothing or a word that is no noun after
    it): "the printing schedule" is a schedule, a paper, with "printing" its modifier."""
    return n + 1 >= len(words) or "NOUN" not in language.lemmas(words[n + 1])


def _office_verbs_gerund(terms: Terms, word: str) -> bool:
    lemmas = language.verb_lemmas(word)
    return word not in lemmas and bool(lemmas & (terms.lex.cue_words | terms.service_verbs))


def _after_of(piece: Piece, start: int) -> bool:
    """Whether token ``start`` of the piece comes after its "of"."""
    tokens = piece.lexed.tokens
    of = next((n for n, t in enumerate(tokens) if t.word == "of"), len(tokens))
    return start > of
