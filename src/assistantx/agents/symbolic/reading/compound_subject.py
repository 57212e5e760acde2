"""A noun that modifies the noun after it in a statement's subject is no verb: "the crew list
needs the clerk's stamp on it" says what the crew list needs, though "crew" is also the past
of "crow"; "this film roll needs splicing", "my stock list needs stamping" alike. English
puts a noun phrase after a determiner, and two nouns in a row there are one thing (a noun
compound, its head perhaps a word the dictionary lacks: "crew rota") whose verb comes after
them; where that verb is a need ("needs", "wants"), the first noun is never the clause's
verb. A verb that is no noun ("the printer jammed") and a
subject of one word ("Hal printed his rota") are read as before."""

from __future__ import annotations

from collections.abc import Collection

from assistantx.core import language

# What opens a noun phrase before a compound subject: articles, possessives, demonstratives.
_OPENERS = frozenset({"the", "a", "an", "my", "your", "our", "their", "his", "her", "its"})
_DEMONSTRATIVES = frozenset({"this", "that", "these", "those"})


def compound_modifier(w: list[str], n: int, needs: Collection[str]) -> bool:
    """Whether ``w[n]`` is a noun opening a two-noun subject that a need verb follows
    ("the *crew* list needs ...")."""
    if n < 1 or n + 2 >= len(w) or w[n - 1] not in _OPENERS | _DEMONSTRATIVES:
        return False
    head = w[n + 1]  # a noun, or a word the dictionary does not know ("rota")
    known = language.is_noun(head) or not language.lemmas(head)
    return language.is_noun(w[n]) and known and w[n + 2] in needs
