"""A person's own place as where something is handed to them: "at Hal's desk", "on her desk",
"leave one in his office".

The reader (``agents.symbolic.reading._parties``) and the runtime's consent guard
(``runtime.recipients``) both decide with these two functions whether a name or a possessive
pronoun names the one who receives, so the guard is never told less than the reader read: a
hand-over the reader plans to "her desk" is one the guard knows she was named for. The place
must be a person's own place (a desk, an office, a tray), after a preposition of putting or
meeting; "from Hal's desk" is a source, "Hal's stapler" an owner, and neither counts.
"""

from __future__ import annotations

from assistantx.core import english

# The words before a person's place that make it where the item is left for them.
MEET_AT = frozenset({"to", "for", "at", "on", "onto", "in", "into", "by"})
# A person's own places: where a thing left for them is theirs to take.
PLACE_WORDS = english.words("place_words") | frozenset({"tray", "pigeonhole", "inbox", "chair"})
# The possessive pronouns that may stand for a person named before ("her desk", "his office").
PLACE_PRONOUNS = frozenset({"her", "his", "their"})


def names_receiving_place(before: str, after: str) -> bool:
    """Whether a possessive name ("Hal's") between ``before`` and ``after`` (folded words)
    names the person whose place the item is left at: "at Hal's desk", "on Hal's tray"."""
    return before in MEET_AT and after in PLACE_WORDS


def pronoun_receiving_place(before: str, pronoun: str, after: str) -> bool:
    """Whether a possessive pronoun names the receiver by their place: "at her desk", "in
    his office"; the person it stands for is the one person named before it."""
    return pronoun in PLACE_PRONOUNS and names_receiving_place(before, after)
