"""A third person who is nobody of the office wants something: "a visitor wants a coffee",
"my guest needs a pen", "the courier needs a pen".

Said as a fact, this is the same speech act as "Wang wants a coffee": someone else's need,
not the speaker's request, and it is met with "Shall I ...?" before anything moves. Only a
colleague can be handed anything, so the yes brings it to the speaker, who passes it on. The
subject is a noun phrase opened by a determiner whose head names a person by what they are
(``outsider_nouns``, the list the screen's outsider recipients are read with; a plural or
other form by its dictionary lemma: "visitors"), with at most a few describing words between
("the new client") and perhaps whose they are after it ("a friend of mine", "a client of
ours": the double genitive still names the outsider, not the speaker). The want may be said
with a helping verb ("a client of ours could do with a pen", "my friend would like a tea")."""

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
# "a friend *of mine*", "a client *of ours*": whose the outsider is, after the noun
_OF_WHOSE = frozenset({"mine", "ours", "yours", "his", "hers", "theirs"})
# a want said with a helping verb ("could do with", "would like"), after the subject
_HELPED_WANTS = tuple(
    tuple(p.split()) for p in (*english.entries("modal_wants"), *english.entries("need_phrases"))
)
_NEEDS = english.words("need_verbs")
# a person described by what they do, not listed ("the carver", "a new lad"): the articles
# that open the phrase (never a possessive: "my laptop needs a charger" is the speaker's own
# thing), and what opens the thing they need ("needs *a* set square"; a thing's own need is
# of work, "the crew list needs stamping", or of "it")
DESCRIBING_ARTICLES = frozenset({"the", "a", "an", "this", "that"})
LACKED_OPENERS = frozenset({"a", "an", "some", "another", "one"})
_LONGEST_SUBJECT = 6  # "my two young guests of ours" at most


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
    if len(subject) > 3 and subject[-2] == "of" and subject[-1] in _OF_WHOSE:
        subject = subject[:-2]  # "a friend of mine": the friend
    if len(subject) < 2 or subject[0] not in _DETERMINERS:
        return False
    if len(subject) - 2 > _MOST_MODIFIERS:
        return False
    return is_outsider_noun(subject[-1]) and not any(is_outsider_noun(w) for w in subject[1:-1])


def outsider_wants(w: Sequence[str]) -> bool:
    """Whether ``w`` says an outsider wants a thing ("a friend of mine needs a ruler", "a
    client of ours could do with a pen"); not what they must do ("the courier needs to
    sign")."""
    for n in range(2, min(len(w), _LONGEST_SUBJECT + 1)):
        if not outsider_subject(w[:n]):
            continue
        rest = tuple(w[n:])
        if rest[:1] and rest[0] in _NEEDS:
            return rest[1:2] != ("to",)
        if any(rest[: len(p)] == p for p in _HELPED_WANTS):
            return True
    return False
