"""Cut off: "can you take my sample tray to", "take my checklist to the": a request that stops
on a preposition or an article, so where the thing goes (or whose it is) was never said. The
later stages would fill the gap with the requester; instead it is asked, and the answer
completes the sentence (``completed``). A preposition stranded by a clause of its own ("bring
me the tray I asked for", "the battery Joss was talking about") ends a whole sentence, and so
does a participle of vague work ("can you get my pot seen to", ``reading.work_unsaid``)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

# The question's opening, which the answer's reading looks for (``completed``).
CUT_OFF = "Your message seems to be cut off after"
# Words a sentence does not end on unless a clause strands them.
_DANGLING = english.words("cut_off_words")
# A subject or a relative word after the verb: a clause that may strand a preposition.
_CLAUSE = english.words("cut_off_clauses")
# "because the visitor lost *his*": a possessive said for the owner's one, in a reason
_REASONS = english.words("reason_conjunctions")
_POSSESSIVES = frozenset({"his", "her", "their", "our", "your", "my"})
# "my pot seen to", "my bike looked after": vague work said, ending on its particle
_VAGUE_DONE = tuple(tuple(p.split()) for p in english.entries("vague_done"))


def cut_off(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if not piece.acts.request or piece is not msg.pieces[-1] or not piece.words:
        return None
    last = piece.words[-1]
    if last not in _DANGLING or _named_last(piece):
        return None
    if any(tuple(piece.words[-len(p) :]) == p for p in _VAGUE_DONE):
        return None  # "can you get my pot seen to": work on it wanted, nothing left hanging
    if last in _POSSESSIVES and _REASONS.intersection(piece.words[:-1]):
        return None  # "I need scissors because the visitor lost his": his one, said why
    after_verb = piece.words[piece.verb_at(terms.en.lead_in) + 1 : -1]
    if set(after_verb) & _CLAUSE:
        return None  # "bring me the tray I asked for": stranded by its own clause
    return Finding(
        "unplaced",
        piece,
        "the message stops mid-sentence: where it goes was not said",
        message=f'{CUT_OFF} "{last}": where should it go, or who should get it?',
    )


def _named_last(piece: Piece) -> bool:
    """The last word is part of a name of the office ("take my timer to Jude A": her
    initial), not a word left hanging."""
    last = len(piece.lexed.tokens) - 1
    return any(
        m.start <= last < m.end and m.kind in ("person", "place", "facility", "item")
        for m in piece.lexed.mentions
    )


def completed(text: str, question: str, answer: str) -> str | None:
    """The cut-off ``text`` with ``answer`` to its question appended ("... to" + "Joss" or
    "to Joss": "... to Joss"); None for any other question."""
    if not question.startswith(CUT_OFF):
        return None
    said = text.rstrip(" .!?…")
    last = said.split()[-1].lower() if said.split() else ""
    rest = answer.strip().rstrip(" .!?")
    if rest.lower().split()[:1] == [last]:
        rest = rest.split(None, 1)[1] if len(rest.split()) > 1 else ""
    return f"{said} {rest}" if rest else None
