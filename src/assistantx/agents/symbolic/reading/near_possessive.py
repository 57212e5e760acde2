"""A thing put down next to a colleague's own, said by the owner alone: "put the ruler next to
Mark's", "leave the calculator beside Will's", "pop my stapler by Zhang's please".

The possessive with no noun of its own stands for the owner's thing of the same kind ("Mark's"
is Mark's ruler), and a word of nearness before it makes it a place: where the thing is put,
which is where that thing is kept, its owner's own place. Read as "at Mark's desk", the
thing is delivered there, one errand; left as it was, the bare possessive was read as a
second thing asked for and the owner's own ruler was fetched as well (a wrong physical
action). Only after a verb of putting a thing down in the same sentence: "bring me the ruler
next to Mark's" describes which ruler, where it lies, and is read as before; so is a noun after
the possessive ("next to Mark's desk", "beside Will's lamp")."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import english

_NEARNESS = sorted(english.entries("nearness_phrases"), key=lambda p: -len(p.split()))
_PUTTING = english.words("putting_verbs")
_FOLLOWERS = english.words("place_possessive_followers")
# the place a colleague's own things are kept: the office's own word for it is read the same
# way ("at Hal's desk" is where Hal receives, core.receiving_place)
_THEIR_PLACE = "desk"

_NEAR_POSSESSIVE = re.compile(
    r"\b(?P<near>"
    + "|".join(r"\s+".join(map(re.escape, p.split())) for p in _NEARNESS)
    + r")\s+(?P<owner>[^\W\d_]+)['’]s\b"
    r"(?=\s*(?P<stop>[,;:.!?]|[-–—]|$)?\s*(?P<next>[^\W\d_]+)?)",
    re.IGNORECASE,
)
_SENTENCE_END = re.compile(r"[.!?;]")
_WORD = re.compile(r"[^\W\d_]+")


def near_possessives(text: str, is_person: Callable[[str], bool]) -> str:
    """``text`` with each "<nearness> <colleague>'s" that names no thing of theirs, after a
    verb of putting down in its sentence, read as "at <colleague>'s desk" (``is_person``:
    whether a word names a colleague)."""

    def placed(match: re.Match[str]) -> str:
        owner = match.group("owner")
        if not is_person(f"{owner}'s"):
            return match.group(0)
        following = (match.group("next") or "").lower()
        if following and not match.group("stop") and following not in _FOLLOWERS:
            return match.group(0)  # "beside Will's lamp": a thing of theirs, read as before
        sentence = _SENTENCE_END.split(text[: match.start()])[-1]
        if not {w.lower() for w in _WORD.findall(sentence)} & _PUTTING:
            return match.group(0)  # "bring me the ruler next to Mark's": which one, where
        return f"at {owner}'s {_THEIR_PLACE}"

    return _NEAR_POSSESSIVE.sub(placed, text)
