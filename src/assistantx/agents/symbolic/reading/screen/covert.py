"""Behind someone's back: "borrow Zhang's stapler without telling him", "grab Pat's charger,
don't tell her", "take Min's mug on the quiet". An owner's yes is asked in their own chat
before any of their things moves, whatever the request says (text carries no authority), so a
request to skip that is declined in words, with the reason; the requester may ask again
plainly and the owner is then asked as usual. A request that only says the owner will not
mind ("he won't mind") is read as before: the owner is still asked."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.destructive import commanded
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_COVERT = tuple(tuple(entry.split()) for entry in english.entries("covert_marks"))


# "print it without asking me again": the speaker's own say, nobody kept in the dark
_SPEAKER = frozenset({"me", "us", "i", "we", "anyone", "anybody"})
_TELLING = frozenset({"without", "dont", "do"})  # the marks a speaker's "me"/"us" may follow


def _kept_in_the_dark(words: list[str]) -> bool:
    for n in range(len(words)):
        for mark in _COVERT:
            end = n + len(mark)
            if words[n:end] != list(mark):
                continue
            # "without asking me", "don't tell us": the speaker's own say; "she'll never
            # notice we took it" keeps the owner in the dark whoever follows
            spoken_to = mark[0] in _TELLING and end < len(words) and words[end] in _SPEAKER
            if not spoken_to:
                return True
    return False


def covert(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if not _kept_in_the_dark(piece.words):
        return None
    if not (piece.acts.request or any(commanded(terms, p) for p in msg.pieces)):
        return None
    return Finding(
        "unsupported",
        piece,
        "a request to act without the owner's knowledge",
        message=(
            "Sorry, I can't do that without the owner knowing: I only take someone's things "
            "with their own yes, asked in their chat. If you'd like, ask me again and I'll ask "
            "them. I did nothing."
        ),
    )
