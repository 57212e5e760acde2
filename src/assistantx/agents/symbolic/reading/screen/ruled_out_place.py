"""A place ruled out beside a where-question: "where's Wang's stapler? not on his desk",
"where is the tape? it's not in the drawer", "where are my scissors, they aren't at
reception". Saying where a thing is not tells where the speaker already looked; it asks
nothing of its own, so the question before it is answered in words as ever and nothing moves.

Read by its shape, whatever the office: after an earlier piece that is an information
question, a piece that is only a negation ("not", "isn't", "aren't", optionally after "it
is"/"they are") followed by a place word ("on", "in", "at", ...), with no task word of its
own ("not on his desk, bring me yours" keeps its request)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import english

_PLACE = english.words("whereabouts_places")
# The subject and verb a negated place may open with ("it's not", "they aren't", "isn't").
_SUBJECTS = frozenset({"it", "its", "they", "theyre", "he", "hes", "she", "shes", "thats"})
_BE = frozenset({"is", "are", "s", "was", "were"})
_NOT = frozenset({"not", "isnt", "arent", "wasnt", "werent", "aint", "nowhere"})


def ruled_out_place(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    acts = piece.acts
    if acts.request or acts.imperative or acts.question is not None:
        return None
    if not _negated_place(content(piece.words)):
        return None
    if any(m.kind == "cue" for m in piece.lexed.mentions):
        return None  # "not on his desk, bring me yours": a task word of its own
    before = [p for p in msg.pieces if p.end <= piece.start]
    if not any(p.acts.question == "info" for p in before):
        return None  # alone, "not on his desk" says nothing the reader can answer
    return Finding("statement", piece, "a place ruled out beside a where-question")


def _negated_place(words: list[str]) -> bool:
    """ "not on his desk", "it's not in the drawer", "they aren't at reception"."""
    w = list(words)
    if w[:1] and w[0] in _SUBJECTS:
        w = w[1:]
    if w[:1] and w[0] in _BE:
        w = w[1:]
    if not w or w[0] not in _NOT:
        return False
    return len(w) > 1 and w[1] in _PLACE
