"""A word of sequence that opens a clause ("print my file, then have Wang sign my contract",
"..., afterwards get Zhang to stamp it") joins the clause to the one before, as "and"
does: it is never the clause's subject, so whether the clause tells or asks is read from the
words after it ("then I'll have Wang sign it" is still the speaker's own plan)."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.core import language

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


# the verbs that would make "<thing> <participle>" a clause that tells ("it was signed")
_AUXILIARIES = frozenset({"is", "was", "are", "were", "be", "been", "has", "had", "have", "s"})


def wanted_done_by(words: Sequence[str]) -> bool:
    """Whether a clause after a word of sequence is a thing and the work wanted done on it by
    someone, with no verb of its own ("then the original signed by Dr Rao"): a past
    participle right before "by" and no auxiliary, a reduced passive that says what is
    wanted, never a statement that it happened ("then the stapler broke", "then it was signed
    by Wang")."""
    if _AUXILIARIES.intersection(words):
        return False
    return any(
        words[n + 1] == "by" and language.is_past_participle(words[n])
        for n in range(1, len(words) - 1)
    )
