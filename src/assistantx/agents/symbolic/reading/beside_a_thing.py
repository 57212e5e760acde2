"""A thing to be put down beside a colleague's thing: "leave the calculator beside Will's
lamp", "put the ruler next to Mark's monitor".

The robot hands things over, or leaves them at a colleague's place; it cannot set a thing
beside another thing. Read as it was, the putting was lost and the thing was fetched for the
speaker (a wrong physical action). A word of nearness, then a colleague's possessive and a
noun that is not their place, after a verb of putting in the same sentence, is said to be out
of reach, and nothing moves. Next to their place ("next to Mark's desk") or their own thing
of the same kind said bare ("next to Mark's", reading/near_possessive.py) is a place the
robot can leave it, read as before; so is the speaker telling what they did ("I put the
ruler next to Mark's lamp")."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import english

_NEARNESS = sorted(english.entries("nearness_phrases"), key=lambda p: -len(p.split()))
_PUTTING = english.words("putting_verbs")
_FOLLOWERS = english.words("place_possessive_followers")
# a colleague's own place, where the robot can leave a thing
_THEIR_PLACE = frozenset({"desk", "table", "workstation", "place", "spot", "chair", "seat"})
# "I put it beside ...": the speaker tells what was done, nothing asked
_SUBJECTS = frozenset({"i", "we", "he", "she", "they", "you", "who"})

_BESIDE = re.compile(
    r"\b(?P<near>"
    + "|".join(r"\s+".join(map(re.escape, p.split())) for p in _NEARNESS)
    + r")\s+(?P<owner>[^\W\d_]+)['’]s\s+(?P<noun>[^\W\d_]+)\b",
    re.IGNORECASE,
)
_SENTENCE_END = re.compile(r"[.!?;]")
_WORD = re.compile(r"[^\W\d_]+")


def beside_a_thing(text: str, is_person: Callable[[str], bool]) -> str | None:
    """What to say where ``text`` asks for a thing to be put beside a colleague's thing (not
    their place), or None (``is_person``: whether a word names a colleague)."""
    for match in _BESIDE.finditer(text):
        owner, noun = match.group("owner"), match.group("noun")
        if not is_person(f"{owner}'s") or noun.lower() in _THEIR_PLACE | _FOLLOWERS:
            continue
        words = [w.lower() for w in _WORD.findall(_SENTENCE_END.split(text[: match.start()])[-1])]
        put = next((i for i, w in enumerate(words) if w in _PUTTING), None)
        if put is None or (put > 0 and words[put - 1] in _SUBJECTS):
            continue
        return (
            f"Sorry, I can't place things beside {owner}'s {noun}: I can only hand a thing "
            f"over or leave it at someone's desk. Tell me if it should go to {owner}'s desk."
        )
    return None
