"""Whose an item is, where a question or statement beside the request says it by a pronoun
or with an adverb in the way: "does Wang still have *his* stapler?", "does Mark *still*
have a ruler?". "his"/"her"/"their" right before the item is the one colleague the message
names (``the_one_named``), as "Wang's" would be; an adverb between the colleague and the verb
of having ("still", "already") says when, not whether, so it is passed over, as a
determiner is. A negation ("Wang never has one") says the opposite and is never passed."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Lexed, Mention
from assistantx.core import english, language

_OTHERS_POSSESSIVES = frozenset({"his", "her", "their", "hers", "theirs"})
_NEGATIONS = english.words("statement_negations") | english.words("negative_adverbs")


def pronoun_owner(lexed: Lexed, before: Mention, named_once: str | None) -> str | None:
    """The colleague a possessive pronoun right before an item means: the one the message
    names, if exactly one; None otherwise (asked, never guessed)."""
    if before.kind != "pronoun" or not before.possessive:
        return None
    if lexed.tokens[before.start].word not in _OTHERS_POSSESSIVES:
        return None
    return named_once


def passed_over(word: str) -> bool:
    """Whether ``word`` between a colleague and the verb of having only says when or how
    surely ("still", "already", "definitely"), never that they do not have it."""
    return word not in _NEGATIONS and "ADV" in language.lemmas(word)
