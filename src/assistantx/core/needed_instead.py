"""A correction said as someone's need of the thing ("take my file to Wang, no wait, Zhang
needs it first"): who needs "it" is who it goes to instead, so the correction names that
person, not news about them. One rule, read by the reader (``screen.correction``) and by the
consent guard (``runtime.recipients``), so the guard lets through the hand-over the reading
asks for."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.core import english

_NEED = english.words("need_verbs")
# the thing just asked for, said again by its pronoun: "needs *it*", "wants *them*"
_THE_THING = frozenset({"it", "them", "that", "this"})
# the most words after the pronoun ("first", "more urgently"); a longer tail ("for the meeting
# at the lab") may name another thing or place, and is left as told
_MOST_AFTER = 2


def needs_the_thing(after: Sequence[str]) -> bool:
    """Whether the words after a correction's subject, to the end of its clause, are only its
    need of the thing just asked for: "needs it", "wants them first". A need of another thing
    ("needs a pen") is news, not a correction."""
    return (
        len(after) >= 2
        and after[0] in _NEED
        and after[1] in _THE_THING
        and len(after) - 2 <= _MOST_AFTER
    )


def needer_end(words: Sequence[str]) -> int | None:
    """Where the subject of "<someone> needs it" ends in a correction's words (the need verb's
    index), when the whole correction is that need; else None."""
    at = next((n for n, w in enumerate(words) if w in _NEED), None)
    if not at or not needs_the_thing(words[at:]):
        return None
    return at
