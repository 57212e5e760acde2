"""How a place or facility feels, said as a complaint: "drying room's absolutely roasting
again", "the copy room's really stuffy today". After the facility and its "is" ("'s"), a few
words of degree ("absolutely", "really") and one word of state, an adjective ("stuffy",
"freezing") or a participle said as one ("roasting", "heaving"), end the clause, with only
the tails a state takes ("again", "today", "btw"). That is a statement, answered in words:
the facility's name is no request for its service ("drying" is no "dry this"), and there is
no fault to repair. A participle of one of the office's services ("the printer's printing")
is its work, read as before."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.core import english, language

_DEGREE = english.words("degree_words")
_TAILS = english.words("state_tails") | frozenset({"too", "atm", "rn", "lately", "still"})


def felt_state(told: Sequence[str], service_verbs: frozenset[str]) -> list[str] | None:
    """The state said ("absolutely roasting"), where ``told`` (the words after the "is") is
    only degree words, one word of state and tails; None otherwise. ``service_verbs``: the
    verbs that ask for one of the office's services, whose participles are its work."""
    n = 0
    while n < len(told) and told[n] in _DEGREE:
        n += 1
    if n >= len(told) or not _a_state(told[n], service_verbs):
        return None
    if not all(w in _TAILS for w in told[n + 1 :]):
        return None
    return list(told[: n + 1])


def _a_state(word: str, service_verbs: frozenset[str]) -> bool:
    """Whether ``word`` says how something is: an adjective, or a present participle said as
    one ("roasting") that is no service's work."""
    if "ADJ" in language.lemmas(word):
        return not language.verb_lemmas(word) & service_verbs or not word.endswith("ing")
    if not language.is_present_participle(word):
        return False
    return not language.verb_lemmas(word) & service_verbs
