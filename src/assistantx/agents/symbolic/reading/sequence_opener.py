"""A word of sequence that opens a clause ("print my file, then have Wang sign my contract",
"..., afterwards get Zhang to stamp it") joins the clause to the one before, as "and"
does: it is never the clause's subject, so whether the clause tells or asks is read from the
words after it ("then I'll have Wang sign it" is still the speaker's own plan)."""

from __future__ import annotations

from collections.abc import Sequence

# Said first in a clause, each says only "after the last thing": no subject, no verb.
_SEQUENCE = (("then",), ("afterwards",))


def after_sequence_word(words: Sequence[str]) -> list[str]:
    """The clause's words after any opening words of sequence ("then", "afterwards")."""
    w = list(words)
    found = True
    while found:
        found = False
        for phrase in _SEQUENCE:
            if tuple(w[: len(phrase)]) == phrase and len(w) > len(phrase):
                w = w[len(phrase) :]
                found = True
    return w
