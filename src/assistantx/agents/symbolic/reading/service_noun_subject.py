"""A service's word said as the subject of a clause: "courier leaves at 3", "post goes at 4",
"print is too small on this form", "water runs out fast". Many words of services are nouns
too (the courier, the post, the print, the water), and an imperative is never followed by a
verb that agrees with its word as a subject: a form of "be" or "have" ("is", "was", "has")
right after it, or a verb in -s followed by when or how it happens ("leaves at 3", "comes
around noon", "runs out", "goes early"), makes the word that clause's subject, and the
clause a statement about it (context beside a request, never the service asked for). A verb
in -s that is also a plural noun is read as the verb only with such a tail, and never when
it names a thing of the office ("copy files at 3": the files are copied).

When the service comes is told the same way ("courier's due at 3", "courier's coming at 3",
"post's going at 4", "courier coming at 3"): a deadline, context for the request beside it,
never the service asked for (a museum's "Courier's due at 3." asked which item to courier).

News of the one who does the service, or of the service come and gone, is told the same way:
"courier just rang", "courier called, he'll be late", "the post came", "printer guy rang back".
A past form after the word (adverbs such as "just" or "already" between them) is that
clause's verb, which an imperative never has; a past form that is also a participle
("called", "dropped") only so when nothing after it could be the object it describes
("courier called back", not "shred signed forms"). A person noun after the service's word
("printer guy", "courier man") makes its doer the subject."""

from __future__ import annotations

from collections.abc import Callable, Collection

from assistantx.agents.symbolic.reading.future_need import clock_time
from assistantx.agents.symbolic.reading.service_command import english_service_verbs
from assistantx.core import english, language

# Forms of "be" and "have" that agree with a singular subject: after a bare service word
# they can only be its verb ("print is too small", "post has gone").
_SINGULAR_BE_HAVE = frozenset(
    {"is", "isnt", "was", "wasnt", "has", "hasnt", "seems", "looks", "gets", "got"}
)
# What may open the subject before the service's word ("the post goes at 4", "our water
# has run out"); never a word that could be the object of the service's verb after it.
_SUBJECT_OPENERS = frozenset({"the", "our", "this", "that", "your", "todays", "tomorrows"})
# "courier *just* rang", "post *already* came": adverbs between a subject and its verb
_BETWEEN = english.words("contracted_adverbs")
# "printer guy rang back", "the courier bloke is here": a person named by what they are
_DOER_NOUNS = english.words("outsider_nouns")
# what may follow a past form told as news with nothing for it to describe: "rang back",
# "called to say", "came and went", "left early" (an adverb: ``_how_or_when``)
_NEWS_TAILS = frozenset({"back", "to", "and", "but", "so", "round", "by", "in", "earlier"})


def service_noun_subject(
    w: list[str],
    office_verbs: Collection[str] = (),
    items: Collection[str] = (),
    named: Callable[[str], bool] = lambda _: False,
) -> bool:
    """Whether the content words ``w`` open with a service's word (English's, the standard
    services' or ``office_verbs``) as the subject of the verb after it; ``items``: the
    office's names of things, which after a service's word are its object; ``named``: whether
    a word is a word of a colleague's name ("print Rose my file": Rose, no past of "rise")."""
    k = 1 if w[:1] and w[0] in _SUBJECT_OPENERS else 0
    if k + 1 >= len(w):
        return False
    word, verb, tail = w[k], w[k + 1], w[k + 2 :]
    services = english_service_verbs() | frozenset(office_verbs)
    if word in services and _news_of(w[k + 1 :], items, named):
        return True  # "courier just rang", "printer guy rang back": the doer, told of
    # checked before the word's own forms: the office's verbs hold "couriers" too, and
    # "courier's due" is no imperative either way
    if _folded_is(word, services, verb):
        return True  # "post's late today": "'s" folded into the word, a state after it
    if word not in services:
        return False
    if not language.is_noun(word):
        return False  # "type", "pay" with no noun reading: only a verb
    if _when_it_comes(verb, tail):
        return True  # "courier coming at 3", "courier due at 3": said without its "is"
    if verb in _SINGULAR_BE_HAVE:
        return True  # "print is too small on this form"
    if not verb.endswith("s") or not language.is_finite_verb(verb) or verb in items:
        return False  # "print labels", "copy files": a plural object, or a thing we keep
    if f"{word} {verb}" in items:
        return False  # "shredder bags to Tomas": the two words name a thing we keep
    return clock_time(tail[:2]) or _how_or_when(tail[:1])


def _folded_is(word: str, services: Collection[str], after: str) -> bool:
    """ "post's late", "courier's gone": a service's word whose "'s" (is, has) was folded
    into it, then a participle, or a word of state or time."""
    if not word.endswith("s") or word[:-1] not in services:
        return False
    return (
        language.is_past_participle(after)
        or language.is_present_participle(after)  # "courier's coming", "post's going"
        or _how_or_when([after])
    )


def _when_it_comes(after: str, tail: list[str]) -> bool:
    """ "coming at 3", "due at 3": an -ing form or a word of state (never a verb's bare
    form, which an imperative's object could follow) right before a time of day: what the
    service's word, said as a subject without its "is", does or is then."""
    if not clock_time(tail[:2]) or tail[:1] != ["at"]:
        return False
    if language.is_present_participle(after):
        return True
    kinds = set(language.lemmas(after))
    return "ADJ" in kinds and not kinds & {"VERB", "DET", "PRON"}


def _how_or_when(words: list[str]) -> bool:
    """ "again", "early", "out", "today": a word that can say how or when (an adverb) and
    cannot open an object (no determiner, pronoun or office thing starts with one)."""
    if not words:
        return False
    kinds = set(language.lemmas(words[0]))
    return "ADV" in kinds and not kinds & {"DET", "PRON"}


def _news_of(rest: list[str], items: Collection[str], named: Callable[[str], bool]) -> bool:
    """Whether ``rest`` (the words after a service's word) tells news of it or of whoever does
    it: a person noun may come first ("guy rang back"), adverbs may stand before the verb
    ("just rang"), and the verb is a past form: a past-only one ("rang", "came", "went")
    anyhow, one that is also a participle ("called", "dropped") only where nothing after it
    could be the thing it describes ("called", "called back", "dropped by earlier")."""
    n = 1 if rest[:1] and rest[0] in _DOER_NOUNS and rest[0] not in items else 0
    while n < len(rest) and rest[n] in _BETWEEN:
        n += 1
    if n >= len(rest) or rest[n] in items or named(rest[n]):
        return False  # "print Rose my file": the one it is for, no verb
    verb, tail = rest[n], rest[n + 1 :]
    if not language.is_past_verb(verb) or not language.is_finite_verb(verb):
        return False
    if not language.is_past_participle(verb):
        return True  # "rang", "came", "went": only a past, never an object's modifier
    return not tail or tail[0] in _NEWS_TAILS or clock_time(tail[:2]) or _how_or_when(tail[:1])
