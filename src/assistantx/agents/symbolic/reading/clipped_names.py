"""A place's one-word name said clipped, as people say it: "repro" for "Reprographics" (or
"Reprographics room")
(the lexicon stage, when its tables are built).

The clipped form must be a word in use (``language.zipf`` at least ``_IN_USE``) that is no
dictionary word of its own ("photo" stays a photo), at least five letters and three short
of the name, and clip only one name of the office; it names nothing else of the office.
"""

from __future__ import annotations

from collections.abc import Collection, Iterable

from assistantx.core import language

# "Reprographics room", "Reprographics office": the room is the one word before a word that
# only says it is a room, so "repro" clips it too.
_ROOM_WORDS = frozenset({"room", "office", "area", "suite", "centre", "center"})
_SHORTEST = 5
_SHORT_BY = 3
_IN_USE = 2.0


def clipped_names(names: Iterable[tuple[str, str]], taken: Collection[str]) -> dict[str, str]:
    """Clipped form → id, for each one-word ``(name key, id)`` pair; ``taken``: the keys the
    office already uses (a clipped form never replaces one)."""
    found: dict[str, set[str]] = {}
    for name, ident in names:
        key = _head(name)
        if key is None or not key.isalpha():
            continue
        for end in range(_SHORTEST, len(key) - _SHORT_BY + 1):
            clip = key[:end]
            if clip in taken or language.is_english_word(clip):
                continue
            if language.zipf(clip) >= _IN_USE:
                found.setdefault(clip, set()).add(ident)
    return {clip: next(iter(ids)) for clip, ids in found.items() if len(ids) == 1}


def _head(key: str) -> str | None:
    """The word a place's name may be clipped from: a one-word name, or the first of two
    where the second only says it is a room ("reprographics room")."""
    words = key.split(" ")
    if len(words) == 1:
        return words[0]
    if len(words) == 2 and words[1] in _ROOM_WORDS:
        return words[0]
    return None
