"""What a told state means for the day, said as "so no <thing>": "printer's down till
tomorrow, so no printing", "Wang's away till Friday fyi, so no signatures this week", "the
binder's off till Monday, so no rehairs this week".

A consequence's "so" (``consequence_joins``) followed by "no" and a noun phrase, with no
request wording of its own, after a piece that tells something and asks nothing, says what
will not happen because of it: a statement, answered in words, and nothing moves. The
service's word after the "no" ("printing", "rehairs") is what the state rules out, never a
service asked for. A request after the "so" ("so can you get Zhang to sign it instead?") is
still one, and so is a request after the consequence ("..., so no printing. bring me a pen":
the pen is asked, the printing still not)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_SO = english.words("consequence_joins")
_FILLERS = english.words("consequence_fillers") | frozenset({"and", "but", "then"})
# "so no printing", "so there's no printing", "so nothing to sign": the negative quantifier
_NONE = frozenset({"no", "nothing", "none"})
_THERE = frozenset({"there", "theres", "therell", "will", "be", "is", "s", "ll", "won't"})


def _asks(piece: Piece) -> bool:
    acts = piece.acts
    return piece.asks or acts.imperative or acts.question is not None or "?" in piece.text


def _ruled_out(words: list[str]) -> bool:
    """Whether the words open with "so" and say that nothing of something will be had."""
    k = 0
    while k < len(words) and words[k] in _FILLERS:
        k += 1
    if k >= len(words) or words[k] not in _SO:
        return False
    k += 1
    while k < len(words) and (words[k] in _FILLERS or words[k] in _THERE):
        k += 1
    return k + 1 < len(words) and words[k] in _NONE


def nothing_follows(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    del terms, requester
    if not _ruled_out(piece.words) or _asks(piece):
        return None
    before = [p for p in msg.pieces if p.end <= piece.start]
    if not before or any(_asks(p) or p.acts.request for p in before):
        return None  # said alone, or after a request: read as before
    return Finding("statement", piece, "what a told state rules out, asking nothing")
