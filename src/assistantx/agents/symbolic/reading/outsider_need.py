"""A third person who is nobody of the office wants something: "a visitor wants a coffee",
"my guest needs a pen", "the courier needs a pen".

Said as a fact, this is the same speech act as "Wang wants a coffee": someone else's need,
not the speaker's request, and it is met with "Shall I ...?" before anything moves. Only a
colleague can be handed anything, so the yes brings it to the speaker, who passes it on. The
subject is a noun phrase opened by a determiner whose head names a person by what they are
(``outsider_nouns``, the list the screen's outsider recipients are read with; a plural or
other form by its dictionary lemma: "visitors"), with at most a few describing words between
("the new client")."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.core import english, language

_OUTSIDERS = english.words("outsider_nouns")
# what opens the subject's phrase: an article, a possessive, a demonstrative
_DETERMINERS = frozenset(
    {"a", "an", "the", "my", "our", "your", "his", "her", "their", "this", "that", "these"}
    | {"those", "some", "another", "one", "two", "three"}
)
# "someone", "people": a person by no description at all; "someone needs a pen" is left to
# the readings that take it as the speaker's indirect request
_UNDESCRIBED = frozenset({"someone", "somebody", "person", "people"})
_MOST_MODIFIERS = 2  # "the new client", "my two young guests"


def is_outsider_noun(word: str) -> bool:
    """A noun that names a person by what they are ("visitor", "clients", "courier")."""
    if word in _UNDESCRIBED:
        return False
    if word in _OUTSIDERS:
        return True
    return bool(set(language.lemmas(word).get("NOUN", ())) & (_OUTSIDERS - _UNDESCRIBED))


def outsider_subject(subject: Sequence[str]) -> bool:
    """Whether ``subject`` (the words before the verb) is a determiner, at most a few
    describing words, and a noun naming a person by what they are ("a visitor")."""
    if len(subject) < 2 or subject[0] not in _DETERMINERS:
        return False
    if len(subject) - 2 > _MOST_MODIFIERS:
        return False
    return is_outsider_noun(subject[-1]) and not any(is_outsider_noun(w) for w in subject[1:-1])
