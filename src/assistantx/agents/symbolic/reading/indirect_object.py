"""The indirect object of a giving or making verb: whom the thing made or brought is for.

English puts the one who gets the thing between the verb and the thing, with no preposition:
"make Zhang a copy of my report", "print Mark a copy of my file", "print Rose my file",
"get Grace a coffee", "make him two copies". The person (or object pronoun) right after the
verb is the recipient when the words after it open the thing's noun phrase (an article, a
possessive, a number). That is what tells it from the causative "make Mark print it", "have
Holly sign it", where a bare verb follows the person and the person is the doer.

The verb is one of the English giving verbs (``dative_verbs``: make, get, bring ...) or one
of the office's own task words ("print", "scan", "brew": a cue mention), so an office whose
services are named by other verbs reads the same way; a person's own work ("sign", "seal")
is no making of a thing for someone and is left to the doer rules.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language, task_kinds

_DATIVE_VERBS = english.words("dative_verbs")
# The words that open a noun phrase after the person: "a", "my", "some", "the", "two".
_OPENERS = (
    english.words("object_starts")
    | english.words("number_words")
    | frozenset({"another", "any", "an", "both", "more", "extra", "spare"})
)
_PERSON_WORK = frozenset(task_kinds.person_kinds())


def opens_noun_phrase(tokens: Sequence[Token], at: int) -> bool:
    """Whether token ``at`` opens a noun phrase: an article or determiner, a number word or
    figure ("2 copies"), or a possessive name ("Wang's file")."""
    if at >= len(tokens) or tokens[at].opens or tokens[at].after_pause:
        return False
    token = tokens[at]
    return token.word in _OPENERS or token.word.isdigit() or token.possessive


def is_giving_verb(word: str) -> bool:
    """Whether ``word`` is a giving verb in any of its forms: "bring", and "bringing" after
    "would you mind", "brought" in a report; the form never changes whom the thing is for."""
    return word in _DATIVE_VERBS or bool(language.verb_lemmas(word) & _DATIVE_VERBS)


def gives_from_verb(tokens: Sequence[Token], ms: Sequence[Mention], n: int, prev: str) -> bool:
    """Whether the word before mention ``n`` (titles skipped: ``prev``) is a giving verb, or
    the office's task word for making something ("print", "scan"), not a person's own work."""
    if is_giving_verb(prev):
        return True
    if n == 0:
        return False
    before = ms[n - 1]
    return (
        before.kind == "cue"
        and before.end <= ms[n].start
        and tokens[before.end - 1].word == prev
        and not any(k in _PERSON_WORK for k in before.ids)
    )


def is_indirect_object(tokens: Sequence[Token], ms: Sequence[Mention], n: int, prev: str) -> bool:
    """Whether mention ``n`` (a person or an object pronoun) is whom a giving or making verb's
    thing is for: right after the verb, with the thing's noun phrase opening right after it
    ("make *Zhang* a copy", "print *her* my file"). A possessive name ("print Zhang's file")
    is read as an owner before this is asked; "her" may be either, and the noun phrase that
    opens after it says it is no possessive here."""
    return gives_from_verb(tokens, ms, n, prev) and opens_noun_phrase(tokens, ms[n].end)
