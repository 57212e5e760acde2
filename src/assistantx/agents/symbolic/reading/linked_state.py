"""How things look, told with a plain linking verb ("the copies look great", "the printouts
seem fine", "these labels feel cheap"): a plural subject agrees with the plain form of
"look", "seem", "feel", "sound", "smell" or "taste", which is also the form a command opens
with ("look for my pen"). After a plural noun that ends a subject opened by a determiner,
and before an adjective (the state), the verb is the subject's and the words a comment:
"thanks, the printouts look great" printed a file and "the copies look great" asked what to
do, when both only say how things turned out. A command never has a subject before its verb,
so a request ("look at the copies") keeps its reading."""

from __future__ import annotations

from assistantx.core import english, language

# the plain (plural-agreeing) linking verbs, which take an adjective, not an object
_LINKING = english.words("plain_linking_verbs")
# chat's words for a thing that works, which the word lists read as no adjective
_CHAT_FINE = frozenset({"ok", "okay", "k", "gud", "alright"})
# the degree words before the adjective ("look *really* good")
_DEGREE = english.words("degree_words")


def linked_state(w: list[str], n: int, subjects: frozenset[str]) -> bool:
    """Whether ``w[n]`` is a plain linking verb agreeing with the plural noun before it, in
    a subject opened by one of ``subjects``, with a state (an adjective) after it."""
    if n < 2 or w[n] not in _LINKING or w[0] not in subjects:
        return False
    if not language.is_plural_noun(w[n - 1]):
        return False  # "you look tired"? no noun; "look great" alone opens no subject
    rest = [x for x in w[n + 1 :] if x not in _DEGREE]
    if not rest:
        return False
    state = rest[0]
    return state in _CHAT_FINE or "ADJ" in language.lemmas(state)
