"""Said beside a question, how it is meant: "who's got a ruler? just curious, not urgent".
Curiosity ("just curious", "only wondering", "out of curiosity") says the question asks no
errand, so it is answered in words with no "Shall I bring you one?"; an unhurried aside ("not
urgent", "no rush") says nothing to do of its own, so it is no request to puzzle over either.
Beside a request ("bring me a ruler, no rush") the request is read as ever.

A moment asked for ("give me a min to find another", "gimme a sec", "hang on a tick", "just a
mo") is the speaker's own pause: its "give me" asks for no thing and its "min" is no colleague
nor anything of the office, so it is told in words (``asks_for_time``). A thing after the
while is still a thing asked for ("give me a second pair of clippers")."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.screen.timing import is_while_noun
from assistantx.core import english, language

# The meaning of a finding of curiosity: the answer beside it offers nothing (``answer``).
CURIOUS = "curiosity: the question asks no errand"

_CURIOSITY = (
    ("curious",),
    ("wondering",),
    ("asking",),
    ("out", "of", "curiosity"),
    ("curiosity",),
)
_UNHURRIED = (
    ("not", "urgent"),
    ("no", "rush"),
    ("no", "hurry"),
    ("not", "important"),
    ("nothing", "urgent"),
)
# Words that only soften the phrase ("I'm just curious", "purely out of curiosity tho").
_SOFTENERS = frozenset(
    {"i", "im", "am", "was", "just", "only", "purely", "really", "tho", "though", "btw", "lol"}
)


_MOMENT_ASKERS = tuple(
    sorted({tuple(e.split()) for e in english.entries("moment_askers")}, key=len, reverse=True)
)
_MOMENT_TAILS = english.words("moment_tails")
# "give me *a* sec", "gimme *five* mins", "hang on *one* tick", "give me *a few* minutes"
_HOW_LONG = frozenset(
    {"a", "an", "one", "two", "three", "five", "ten", "few", "couple", "of", "little", "quick"}
    | {"half"}
)
_OPENERS = frozenset({"oh", "ok", "okay", "sorry", "um", "erm", "uh", "hmm", "please", "pls"})


def moment_asked(words: list[str]) -> bool:
    """Whether ``words`` ask for a moment and nothing else: an opener ("give me", "hang
    on"), a while ("a sec"), then nothing or the speaker's own doing ("to find another")."""
    w = list(words)
    while w and w[0] in _OPENERS:
        w = w[1:]
    while w and w[-1] in _OPENERS:
        w = w[:-1]
    opener = next((p for p in _MOMENT_ASKERS if tuple(w[: len(p)]) == p), None)
    if opener is None:
        return False
    rest = w[len(opener) :]
    if opener[-1] == "on" and not rest:
        return True  # "hang on", "hold on"
    if opener == ("bear", "with", "me") and not rest:
        return True
    n = 0
    while n < len(rest) and (
        rest[n] in _HOW_LONG or rest[n].isdigit() or language.is_day_number(rest[n])
    ):
        n += 1
    if n == len(rest) or not is_while_noun(rest[n]):
        return False
    if n == 0 and opener[-1] not in ("on", "wait", "one", "half", "just"):
        return False  # "give me seconds": said with how long, or not at all
    tail = rest[n + 1 :]
    return not tail or tail[0] in _MOMENT_TAILS


def asks_for_time(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """ "give me a min to find another", "hang on a tick": the speaker's pause, asking
    nothing (``moment_asked``)."""
    if piece.acts.question is not None and piece.asks:
        return None
    if not moment_asked(piece.words):
        return None
    return Finding("statement", piece, "asks for a moment: nothing to do")


def _said(words: list[str], phrases: tuple[tuple[str, ...], ...]) -> bool:
    said = tuple(w for w in words if w not in _SOFTENERS)
    return said in phrases


def curious(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if piece.acts.question is not None or piece.acts.request:
        return None
    if not any(p.acts.question is not None for p in msg.pieces if p is not piece):
        return None  # "just curious" alone, or beside a request: read as before
    if _said(piece.words, _CURIOSITY):
        return Finding("statement", piece, CURIOUS)
    if _said(piece.words, _UNHURRIED):
        return Finding("statement", piece, "an aside: no hurry")
    return None
