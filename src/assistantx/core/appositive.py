"""A name in apposition to a receiving phrase: "print off my lesson plan for the cover
teacher, Ms Nguyen", "take it to our new intern, Bo". The person named after the comma is the
one the phrase ("for"/"to" + a determiner and a few words ending in a noun: their role) names,
so they receive what the phrase is for.

The reader (``agents.symbolic.reading._parties``) and the runtime's consent guard
(``runtime.recipients``) decide with this one function, so the guard lets the hand-over the
reader planned go to the person named. The name closes its clause (the text's or sentence's
end, a pause, a courtesy word): "to the post room, June needs it" names June as no receiver.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

from assistantx.core import english, language

_TITLES = english.words("titles") - {"a", "an", "the", "our"}
_DETERMINERS = english.words("determiners")
_COURTESY = english.words("courtesy")
# The most words of a role said before a name in apposition ("the new cover teacher")
ROLE_WORDS_MAX = 4


class Word(Protocol):
    @property
    def word(self) -> str: ...  # folded

    @property
    def opens(self) -> bool: ...  # the first word of a sentence

    @property
    def after_pause(self) -> bool: ...  # a comma (or colon) before it


def appositive_preposition(words: Sequence[Word], start: int, end: int) -> str:
    """The preposition ("for", "to") of the receiving phrase the name at [start, end) stands
    in apposition to, or "" where it stands in none."""
    j = start
    while j > 0 and words[j - 1].word in _TITLES and not words[j].after_pause:
        j -= 1  # "Ms Nguyen": the title opens the name
    if j == 0 or words[j].opens or not words[j].after_pause:
        return ""
    if end < len(words):
        after = words[end]
        if not (after.opens or after.after_pause or after.word in _COURTESY):
            return ""
    k = j - 1  # back over the role's words to its determiner
    while k >= 0 and words[k].word not in _DETERMINERS:
        if words[k].opens or words[k].after_pause or j - k > ROLE_WORDS_MAX:
            return ""
        k -= 1
    if k < 1 or k == j - 1 or words[k].opens or words[k].after_pause:
        return ""
    role_end = words[j - 1].word
    if not (language.is_noun(role_end) or role_end in _TITLES):
        return ""  # the role ends with a noun ("teacher"), not a verb
    return words[k - 1].word
