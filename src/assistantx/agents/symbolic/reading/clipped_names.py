"""A place's name said short, as people say it: "repro" for "Reprographics" (or
"Reprographics room"), "the studio" for the "Digitisation studio"
(the lexicon stage, when its tables are built).

The clipped form must be a word in use (``language.zipf`` at least ``_IN_USE``) that is no
dictionary word of its own ("photo" stays a photo), at least five letters and three short
of the name, and clip only one name of the office; it names nothing else of the office.

An item's one-word name said clipped ("steth" for "stethoscope") is read as that name when
the word is otherwise unknown (``clipped_item``, the lexicon's typo step).
"""

from __future__ import annotations

from collections.abc import Collection, Iterable, Mapping

from assistantx.core import english, language

# "Reprographics room", "Reprographics office": the room is the one word before a word that
# only says it is a room, so "repro" clips it too.
ROOM_WORDS = frozenset({"room", "office", "area", "suite", "centre", "center"})
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


# Head words that do not name one place alone: too general ("the office", "my desk", "the
# floor") or mostly meaning something else ("the post" is the mail, not a "security post").
_NOT_ALONE = ROOM_WORDS | frozenset(
    {"desk", "floor", "corner", "door", "table", "side", "hall", "space", "point", "place"}
    | {"post", "line", "end", "top", "front", "back"}
)
_HEAD_SHORTEST = 3


def place_heads(names: Iterable[tuple[str, str]], taken: Collection[str]) -> dict[str, str]:
    """Head word → id, for the last word of each several-word place name ("studio" of
    "Digitisation studio"), as people say a place once they know which one they mean ("take
    it down to the studio"). Only a head that ends the name of exactly one place, is a word
    (no number), is not too general to name a place alone, and names nothing else of the
    office (``taken``); a letter or number ("Cutting room A") never stands alone."""
    found: dict[str, set[str]] = {}
    for name, ident in names:
        words = name.split(" ")
        head = words[-1]
        if len(words) < 2 or len(head) < _HEAD_SHORTEST or not head.isalpha() or head in _NOT_ALONE:
            continue
        found.setdefault(head, set()).add(ident)
    return {
        head: next(iter(ids))
        for head, ids in found.items()
        if len(ids) == 1 and head not in taken and language.plural(head) not in taken
    }


# A kind of room or place said alone for the office's place its name opens with ("the cafe"
# for "Cafe kitchen"); a town's shop said so is the office's place too ("the pharmacy" for a
# hospital's "Pharmacy hatch").
_ROOM_KINDS = english.words("room_kind_nouns") | frozenset(
    e for e in english.entries("outside_shops") if " " not in e
)


def place_openers(names: Iterable[tuple[str, str]]) -> dict[str, frozenset[str]]:
    """Opening words → ids, for the opening words of each several-word place name that name
    a kind of room or place alone: one such word ("the cafe" of "Cafe counter", "the kitchen"
    of "Kitchen counter"), or several ending in a word that only says it is a room ("the post
    room" of "Post room counter"), as people say a place by the room it is in. Several places
    may open alike ("Cafe counter", "Cafe kitchen"): the words name the office's own room."""
    found: dict[str, set[str]] = {}
    for name, ident in names:
        words = name.split(" ")
        for end in range(1, len(words)):
            last = words[end - 1]
            if last in _ROOM_KINDS or (end > 1 and last in ROOM_WORDS and words[0].isalpha()):
                found.setdefault(" ".join(words[:end]), set()).add(ident)
    return {opener: frozenset(ids) for opener, ids in found.items()}


def _head(key: str) -> str | None:
    """The word a place's name may be clipped from: a one-word name, or the first of two
    where the second only says it is a room ("reprographics room")."""
    words = key.split(" ")
    if len(words) == 1:
        return words[0]
    if len(words) == 2 and words[1] in ROOM_WORDS:
        return words[0]
    return None


# An item's name clipped ("steth" for "stethoscope"): at least this many letters, and this many
# short of the name, so a whole word said with a typo is left to the typo reading.
_ITEM_SHORTEST = 4
_ITEM_SHORT_BY = 2


def clipped_item(word: str, items: Mapping[str, str]) -> str | None:
    """The one-word item name (a key of ``items``, name → item type id) that ``word`` clips:
    "steth" → "stethoscope". Only a word that is no English word or word form ("ther" stays
    "ther"), at least four letters and two short of the name, clipping the names of exactly
    one item type; clipping several ("therm" for a thermometer and a thermos), it names none,
    and the request is asked about as an unknown thing."""
    if len(word) < _ITEM_SHORTEST or not word.isalpha() or language.is_word_form(word):
        return None
    found = {
        ident: key
        for key, ident in items.items()
        if key.isalpha() and len(key) - len(word) >= _ITEM_SHORT_BY and key.startswith(word)
    }
    return next(iter(found.values())) if len(found) == 1 else None
