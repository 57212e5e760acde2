"""An item's name of several words said with its first word clipped: "a *temp* pass" for the
office's "temporary pass", "the *promo* flyers" for its "promotional flyer".

People shorten the describing word of a compound name and keep its head noun. The head noun
must be said as it is (singular or plural); the clipped word is the start of the name's first
word, three letters or more ("ref CD") and at least two short of it, and no function word
("the cup" is no "thermal cup"). Every such form is added to the lexicon's item names at
build time, unless it is already a name of the office or two items' names clip to the same
form (then neither gets it: which was meant is asked, as for any word the office does not
know). A clip that is the first word's own verb ("weigh" of "weighing
scales") is no clip: "need to weigh the salt" is the speaker's doing.
"""

from __future__ import annotations

from collections.abc import Collection, Iterable

from assistantx.core import english, language

_SHORTEST = 3  # "ref CD" for the "reference CD", "temp pass"
_SHORT_BY = 2
# A clip that is a function word is that word ("the cup" is no "thermal cup").
_FUNCTION_WORDS = english.words("common")


def clipped_phrases(names: Iterable[tuple[str, str]], taken: Collection[str]) -> dict[str, str]:
    """Clipped form → item id, for each ``(name key, item id)`` of two words or more;
    ``taken``: the keys the office already uses (never replaced)."""
    found: dict[str, set[str]] = {}
    for key, item in names:
        first, *rest = key.split(" ")
        if not rest or not first.isalpha():
            continue
        for end in range(_SHORTEST, len(first) - _SHORT_BY + 1):
            if first in language.verb_forms(first[:end]):
                continue  # "weigh" of "weighing scales" is the verb itself, no clip
            if first[:end] in _FUNCTION_WORDS:
                continue
            found.setdefault(" ".join([first[:end], *rest]), set()).add(item)
    return {
        form: next(iter(items))
        for form, items in found.items()
        if len(items) == 1 and form not in taken
    }
