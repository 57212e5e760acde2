"""How many words after a purpose's verb belong to the purpose the office declares: "something
to check *continuity* with" where a multimeter's purposes include "check continuity", "to
take *notes* with", "to write *on*". A purpose names its tool by the verb and its object
together, so the object is part of the phrase: never left behind to be glued to the tool's
name ("a multimeter continuity"). The longest declared phrase wins ("check continuity" over
"check"); none: no word (the verb alone is the purpose)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from assistantx.core import english, language

# "check the continuity of the loom" is said, never declared: a purpose is short
_LONGEST_OBJECT = 3


def purpose_words(declared: Callable[[str], list[str]], verb: str, tail: Sequence[str]) -> int:
    """The number of words of ``tail`` (the words after the purpose's verb) that, with
    ``verb``, make the longest purpose ``declared`` knows an item for; 0 when none does."""
    for n in range(min(_LONGEST_OBJECT, len(tail)), 0, -1):
        if declared(" ".join([verb, *(w.lower() for w in tail[:n])])):
            return n
    return 0


# "check the tread depth" said, "check tread depth" listed: an article before the object
# changes nothing about the purpose, so both sides are compared without it
_ARTICLES = frozenset({"a", "an", "the"})


def without_articles(phrase: str) -> str:
    """A purpose's words without "a", "an", "the" ("check the tread" → check tread)."""
    return " ".join(w for w in phrase.lower().split() if w not in _ARTICLES)


def object_nouns(tail: Sequence[str], said: int) -> int:
    """The words of ``tail`` the purpose's object takes up when nouns go on after the declared
    words ("check the tread *wear*" where "check the tread" is declared): a compound the
    object heads is still what the tool works on, never a word glued to the tool's name ("a
    tread depth gauge wear"). Only after an object was said (``said`` > 0); a word the
    dictionary also reads as an adverb, preposition, auxiliary or determiner ends it ("for",
    "today")."""
    n = said
    while 0 < said and n < len(tail) and n - said < _LONGEST_OBJECT and noun_only(tail[n]):
        n += 1
    return n


def noun_only(word: str) -> bool:
    """Whether the dictionary reads ``word`` as a noun and never as an adverb, a
    preposition, an auxiliary, a determiner or a pronoun."""
    found = language.lemmas(word.lower())
    return "NOUN" in found and not found.keys() & {"ADV", "ADP", "AUX", "DET", "PRON"}


# The words that only say which one or whose ("a", "the", "my", "some"): a purpose is the same
# said with or without them ("open *a* parcel" is the declared "open parcels")
_WHICH = frozenset({"a", "an", "the", "my", "our", "your", "his", "her", "their", "some", "any"})


def purpose_key(phrase: str) -> tuple[str, ...]:
    """A purpose's words as compared: no article or possessive, each noun in its singular
    ("open a parcel" and "open parcels": open parcel); the verb as said (already a lemma)."""
    words = [w for w in phrase.lower().split() if w not in _WHICH]
    return tuple(_singular(w) if n else w for n, w in enumerate(words))


def said_as_declared(said: str, declared: str) -> bool:
    """Whether a purpose ``said`` is the ``declared`` one: the same words as compared, or the
    same once a noun that only modifies the next noun is left out ("get *dog* hairs off" is
    the declared "get hair off": the hair is what is got off, whatever animal's)."""
    words, wanted = purpose_key(said), purpose_key(declared)
    if words == wanted:
        return True
    plain = tuple(
        w
        for n, w in enumerate(words)
        if not (0 < n < len(words) - 1 and noun_only(w) and noun_only(words[n + 1]))
    )
    return plain == wanted or _clipped(words, wanted) or _split_particle(words, wanted)


# "cut my pots off" of a declared "cut off": the object of a phrasal verb said between the verb
# and its particle, as English puts a noun object there; up to this many words of it
_SPLIT_OBJECT = 2
PARTICLES = frozenset({"off", "up", "out", "down", "away", "back", "over", "apart", "open"})


def _split_particle(words: tuple[str, ...], wanted: tuple[str, ...]) -> bool:
    """Whether ``words`` are the declared phrasal verb ``wanted`` ("cut off") with an object
    between its verb and its particle ("cut pot off")."""
    if len(wanted) != 2 or wanted[1] not in PARTICLES:
        return False
    between = words[1:-1]
    return (
        len(words) >= 3
        and words[0] == wanted[0]
        and words[-1] == wanted[1]
        and len(between) <= _SPLIT_OBJECT
        and all(noun_only(w) for w in between)
    )


# "check the temps" of a declared "check temperatures": a word of the object said clipped, as
# people type it in chat; at least this many letters, and this many short of the word
_CLIP_SHORTEST = 4
_CLIP_SHORT_BY = 3


def _clipped(words: tuple[str, ...], wanted: tuple[str, ...]) -> bool:
    """Whether ``words`` are ``wanted`` with the verb the same and each object word the same
    or its clipped form ("temp" of "temperature"); the verb is never clipped."""
    if len(words) != len(wanted) or len(words) < 2 or words[0] != wanted[0]:
        return False
    clipped = [
        w != v and any(_clips(c, v) for c in (w, w.removesuffix("s")))  # "temps": temp + s
        for w, v in zip(words[1:], wanted[1:], strict=True)
    ]
    same = [w == v for w, v in zip(words[1:], wanted[1:], strict=True)]
    return any(clipped) and all(c or s for c, s in zip(clipped, same, strict=True))


def _clips(short: str, word: str) -> bool:
    return (
        len(short) >= _CLIP_SHORTEST
        and len(word) - len(short) >= _CLIP_SHORT_BY
        and word.startswith(short)
    )


def _singular(word: str) -> str:
    nouns = language.lemmas(word).get("NOUN", ())
    return min(nouns, key=len) if nouns and noun_only(word) else word


# "something *to* wipe ...", "anything *I can* clean ... with": what says the thing is named by
# the verb after it ("for" names what it is for by a noun: "something for the tea")
_VERB_LINKS = tuple(
    tuple(p.split())
    for p in sorted(english.entries("purpose_links"), key=len, reverse=True)
    if p != "for"
)
_HEADS = tuple(
    tuple(p.split()) for p in sorted(english.entries("purpose_heads"), key=len, reverse=True)
)
_PARTICLES = english.words("verb_particles")  # "wipe *up* the tea", "clean *off* the desk"
_OPENERS = english.words("object_starts") | english.words("determiners")  # "*its* lid"
_SUBJECTS = english.words("subject_pronouns")  # "the tea *I* knocked over": a clause begins


def used_on(words: Sequence[str]) -> range | None:
    """Where, in ``words`` (lower case), the object of a purpose's verb is: "need something to
    wipe up *the tea* I knocked over", "anything to clean *the water* off my desk". A purpose
    names the thing wanted by its verb; what the verb acts on is what it is used on, never a
    thing asked for. None where no purpose's verb has an object ("something to wipe with")."""
    for n in range(len(words)):
        head = next((h for h in _HEADS if tuple(words[n : n + len(h)]) == h), None)
        if head is None:
            continue
        at = n + len(head)
        link = next((k for k in _VERB_LINKS if tuple(words[at : at + len(k)]) == k), None)
        if link is None:
            continue
        verb = at + len(link)
        if verb >= len(words) or words[verb] not in language.verb_lemmas(words[verb]):
            continue
        start = verb + 1
        while start < len(words) and words[start] in _PARTICLES:
            start += 1
        end = start + (start < len(words) and words[start] in _OPENERS)
        first = end
        while end < len(words) and end - first < _LONGEST_OBJECT and _noun_of_object(words[end]):
            end += 1
        if end > first:
            return range(start, end)
    return None


def _noun_of_object(word: str) -> bool:
    return word not in _SUBJECTS and noun_only(word)
