"""A person's own place as where something is handed to them: "at Hal's desk", "on her desk",
"leave one in his office".

The reader (``agents.symbolic.reading._parties``) and the runtime's consent guard
(``runtime.recipients``) both decide with these two functions whether a name or a possessive
pronoun names the one who receives, so the guard is never told less than the reader read: a
hand-over the reader plans to "her desk" is one the guard knows she was named for. The place
must be a person's own place (a desk, an office, a tray), after a preposition of putting or
meeting; "from Hal's desk" is a source, "Hal's stapler" an owner, and neither counts. Nor does
a place that says where the item lies now ("the one on Hal's desk", "the book that's on her
desk", "the file sitting in his office"): that is where it is fetched from.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol

from assistantx.core import english

# The words before a person's place that make it where the item is left for them.
MEET_AT = frozenset({"to", "for", "at", "on", "onto", "in", "into", "by"})
# A person's own places: where a thing left for them is theirs to take.
PLACE_WORDS = english.words("place_words") | frozenset({"tray", "pigeonhole", "inbox", "chair"})
# The possessive pronouns that may stand for a person named before ("her desk", "his office").
PLACE_PRONOUNS = frozenset({"her", "his", "their"})

_LIES_AT = english.words("lies_at_words")
_LIES_AT_CONTRACTED = english.words("lies_at_contracted")  # "that's", "it's": "that is"
_ONES = english.words("lies_at_ones")
_ONES_PICKED = frozenset({"the", "that", "this", "these", "those"})  # "the one", not "leave one"


@dataclass(frozen=True)
class Ahead:
    """The two words before a place's preposition, nearest last ("the", "one" in "the one on
    Hal's desk"), and whether the nearer one was written with a contracted "'s"."""

    words: tuple[str, ...] = ()
    contracted: bool = False


class PlacedWord(Protocol):
    """A word as the reader's ``Token`` and the consent guard's word both carry it."""

    @property
    def word(self) -> str: ...  # folded, without a possessive 's

    @property
    def possessive(self) -> bool: ...

    @property
    def opens(self) -> bool: ...  # the first word of a sentence

    @property
    def after_pause(self) -> bool: ...  # a comma before it


def ahead_at(words: Sequence[PlacedWord], k: int) -> Ahead:
    """The two words before the preposition at ``k``, within its sentence and phrase ("the",
    "one" in "the one on Hal's desk"); nothing where the preposition opens either."""
    if k <= 0 or words[k].opens or words[k].after_pause:
        return Ahead()
    near = words[k - 1]
    far = words[k - 2].word if k >= 2 and not near.opens and not near.after_pause else ""
    return Ahead(words=(far, near.word) if far else (near.word,), contracted=near.possessive)


def lies_there(ahead: Ahead | None) -> bool:
    """Whether the words before the preposition make the place where the item lies now
    ("sitting on", "that's on", "the one on"), not where it is taken ("leave one on")."""
    if ahead is None or not ahead.words:
        return False
    last = ahead.words[-1]
    if ahead.contracted:
        return last in _LIES_AT_CONTRACTED
    if last in _ONES:
        return len(ahead.words) > 1 and ahead.words[-2] in _ONES_PICKED
    return last in _LIES_AT


def names_receiving_place(before: str, after: str, ahead: Ahead | None = None) -> bool:
    """Whether a possessive name ("Hal's") between ``before`` and ``after`` (folded words)
    names the person whose place the item is left at: "at Hal's desk", "on Hal's tray";
    ``ahead``: the words before ``before`` ("the one on Hal's desk" is where it lies)."""
    return before in MEET_AT and after in PLACE_WORDS and not lies_there(ahead)


def pronoun_receiving_place(
    before: str, pronoun: str, after: str, ahead: Ahead | None = None
) -> bool:
    """Whether a possessive pronoun names the receiver by their place: "at her desk", "in
    his office"; the person it stands for is the one person named before it."""
    return pronoun in PLACE_PRONOUNS and names_receiving_place(before, after, ahead)
