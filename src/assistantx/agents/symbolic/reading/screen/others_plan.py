"""A colleague's own plan beside a request: "give Will my letter, she'll frank it later",
"give Lee my document, he will copy it later", "pass May my ruler, she's going to need it".
A clause whose subject is a third person (he, she, they, or a colleague by name) and whose
verb is in the future ("'ll", "will", "shall", "is going to", "gonna") says what that person
will do themselves: the reason for the hand-over, never a service for the robot to run. Read
as asked, the robot franked or copied the thing before handing it over (a wrong physical
action). The speaker's own future ("I'll frank it myself") and a clause alone, with no
request before it, are read as before."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.others_doing import colleague_first
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import language

_THIRD = frozenset({"he", "she", "they"})
# The subject and its auxiliary folded into one word ("she's" → "shes", "they'll" → "theyll"):
# the auxiliary is what is left of it. ("hell", "shell" never reach here: kept apart before.)
_FUSED = {"hes": "s", "shes": "s", "theyre": "re", "theyll": "ll"}
# A future's auxiliary, one word or two ("is going to" / "'s gonna" come as two or three).
_WILL = frozenset({"ll", "will", "shall"})
_BE = frozenset({"is", "s", "are", "re"})
_GOING = (("going", "to"), ("gonna",))
_ADVERBS = frozenset({"probably", "definitely", "just", "also", "still", "likely", "then"})


def others_plan(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if piece.acts.imperative or piece.acts.question is not None or piece.asks:
        return None
    if not any(p.acts.request for p in msg.pieces if p.end <= piece.start):
        return None  # alone, or before the request: read as before
    words = content(piece.words)
    rest = _after_subject(piece, words, requester)
    if rest is None:
        return None
    rest = _after_future(rest)
    if not rest:
        return None
    while rest and rest[0] in _ADVERBS:
        rest = rest[1:]
    if not rest or rest[0] not in language.verb_lemmas(rest[0]):
        return None  # "she'll be fine", no plain verb: a remark read as before
    return Finding("statement", piece, "what a colleague will do themselves: context only")


def _after_subject(piece: Piece, words: list[str], requester: str) -> list[str] | None:
    """The words after the piece's third-person subject ("he", "she", "they", or one
    colleague's name that is not the speaker's); None where it opens with no such subject."""
    if words[:1] and words[0] in _THIRD:
        return words[1:]
    if words[:1] and words[0] in _FUSED:
        return [_FUSED[words[0]], *words[1:]]
    end = colleague_first(piece, requester)
    return None if end is None else content([t.word for t in piece.lexed.tokens[end:]])


def _after_future(words: list[str]) -> list[str] | None:
    """The words after a future's auxiliary opening ``words``; None where there is none."""
    if words[:1] and words[0] in _WILL:
        return words[1:]
    rest = words[1:] if words[:1] and words[0] in _BE else words
    for going in _GOING:
        if tuple(rest[: len(going)]) == going:
            return rest[len(going) :]
    return None
