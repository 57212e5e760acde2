"""A number or letter label after a word: "level 3", "floor 2", "block B", "room 4".

English names one of a numbered series by a noun and its label, and the pair may modify a
noun after it: "the level 3 drawings" are drawings (of level 3), never the office's laser
level; "the floor 2 plans" are plans. So where an office's item name is followed by a label
and then a noun, the item name is the first part of a compound, as "the *wine* list" is
(``compound_heads``), and the noun after the label is what the phrase names. A label alone
after the name ("bring me the level 3") changes nothing: no noun follows for it to modify.

A label is digits ("3", "12"), a capital letter written alone ("B"), or digits and one
letter ("2B", "B2"): the ways a series is numbered. A lower-case letter alone ("a") is a
word, not a label, and so is "I" ("the level I need"): the speaker.
"""

from __future__ import annotations

import re
from collections.abc import Collection, Sequence

from assistantx.agents.symbolic.reading.tokens import Token

_LABEL = re.compile(r"\d{1,4}|[A-HJ-Z]|\d{1,3}[A-Za-z]|[A-Z]\d{1,3}")


def is_label(t: Token) -> bool:
    """Whether ``t`` is a series label as written ("3", "B", "2B"), in the same phrase as the
    word before it."""
    return not (t.opens or t.after_pause) and _LABEL.fullmatch(t.text) is not None


def past_label(tokens: Sequence[Token], at: int) -> int:
    """The token after a label at ``at`` ("level *3* drawings" → the drawings), or ``at``
    where no label stands there."""
    return at + 1 if at < len(tokens) and is_label(tokens[at]) else at


def after_label(tokens: Sequence[Token], at: int) -> bool:
    """Whether the word at ``at`` comes right after a label that follows a word ("floor 2
    *plans*"): a noun the labelled word modifies."""
    return at >= 2 and is_label(tokens[at - 1]) and tokens[at - 2].word.isalpha()


def labels_an_item(tokens: Sequence[Token], end: int, item_starts: Collection[int]) -> bool:
    """Whether an item's name ending at ``end`` is followed by a label and then another of
    the office's items ("the *level* 3 drawings" where "drawings" is the file's synonym): the
    labelled name says which of those is meant, so the thing is the one after the label."""
    at = past_label(tokens, end)
    return (
        at > end
        and at in item_starts
        and not tokens[end - 1].possessive
        and not tokens[at].after_pause
        and tokens[at].text[:1].islower()
    )
