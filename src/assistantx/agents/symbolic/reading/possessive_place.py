"""A colleague's possessive said as a place: "take this book to Wang's if he's in", "bring
the stapler back to Wang's", "take the ruler over to Pat's". After "to", a colleague's
possessive with no noun of its own (the message or the clause ends, or a condition, a "please"
or another clause follows) names their desk, and so them as who receives the thing: it is
read as "to Wang", the same as "to Wang's desk" is. Left as it was, the bare possessive was
read as a second thing asked for ("Wang's stapler" beside "the stapler", both brought to the
speaker): a wrong physical action.

A noun after it ("to Wang's desk", "to Wang's stapler") is left to the frames, and so is a
possessive after a word of nearness ("next to Wang's"): that places, it hands nothing over."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import english

_FOLLOWERS = english.words("place_possessive_followers")
_NEARNESS = english.words("place_possessive_nearness")

# "to" + a name word's possessive (the word before "to" kept to see nearness), and what
# follows it up to the next word looked at, not taken
_TO_POSSESSIVE = re.compile(
    r"(?P<before>\b[^\W\d_]+\s+)?\bto\s+(?:[^\W\d_]+\s+)?(?P<owner>[^\W\d_]+)['’]s\b"
    r"(?=\s*(?P<stop>[,;:.!?]|[-–—]|$)?\s*(?P<next>[^\W\d_]+)?)",
    re.IGNORECASE,
)


def possessive_places(text: str, is_person: Callable[[str], bool]) -> str:
    """``text`` with each "to <colleague>'s" that names no thing of theirs read as "to
    <colleague>" (``is_person``: whether a word names a colleague)."""

    def placed(match: re.Match[str]) -> str:
        before = (match.group("before") or "").strip().lower()
        if before in _NEARNESS:
            return match.group(0)
        owner = match.group("owner")
        if not is_person(f"{owner}'s"):
            return match.group(0)
        following = (match.group("next") or "").lower()
        # nothing after it, a pause before the next word, or a word that opens no noun
        if following and not match.group("stop") and following not in _FOLLOWERS:
            return match.group(0)
        return match.group(0)[: match.end("owner") - match.start(0)]

    return _TO_POSSESSIVE.sub(placed, text)
