"""A thing left with, for or at a named colleague is handed to them: "leave them with Fang",
"leave them for Chen", "leave them on Fang's desk". The verb "leave" also opens wishes about
people ("leave them alone", "leave her be"), and "them"/"her" are words of such wishes; but
a named colleague after "with"/"for", or their desk after "on"/"at", says where the thing
goes, never whom to leave in peace (fix169a class 1: "photocopy my report, 2 copies, and
leave them with Fang" dropped the second clause as a wish and handed the copies to the
speaker). A word of keeping away ("leave them away from Fang") still makes a wish."""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence

from assistantx.core.receiving_place import MEET_AT, PLACE_WORDS

# "with Fang", "for Chen": the one a thing left is for
_HANDED_TO = frozenset({"with", "for"})


def handed_to_named(words: Sequence[str], named: Callable[[str], bool]) -> bool:
    """Whether ``words`` (after the leaving verb) name a colleague, by ``named``, as the one
    the thing is left with or for, or whose desk it is left on."""
    for before, word in itertools.pairwise(words):
        if before in _HANDED_TO and named(word):
            return True  # "with Fang", "for Chen"
    for a, b, c in zip(words, words[1:], words[2:], strict=False):
        # "on Fang's desk": the possessive lexed as "fangs"
        if a in MEET_AT and c in PLACE_WORDS and b.endswith("s") and named(b[:-1]):
            return True
    return False
