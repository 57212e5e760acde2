"""An item named by a unit or a container of it: "a *box of* staples", "a post-it *pad*",
"a copier paper *ream*", "a *pack of* wipes".

English counts stuff and small things by a unit noun (english.yaml ``unit_nouns``): the
thing is named after "of" ("a box of staples") or as the first part of a compound before the
unit ("a post-it pad"), and either way what is wanted is the thing. The office lists its
supplies by their own names, often plural ("post-its", "sticky notes"); a noun used as the
first part of a compound is said in the singular ("a post-it pad", never "a post-its pad"),
and so is one of them ("a post-it"). So:

- a unit noun, "of", then an item's name is that item, the unit and "of" included in the
  mention (nothing is left for a later stage to take for an unknown "box");
- the singular of an item's plural name (its last word's singular, "post it" from "post
  its") is that item where a compound's first part or a counted noun stands: before a unit
  noun, or after an article or a possessive ("a post-it", "my post-it"). A singular of one
  word that is also a verb ("wipe" of "wipes") is the item after an article only where it
  is asked for: right after the one it is for ("bring me a wipe", "hand Zhang a wipe") or a
  verb of asking or having ("I need a wipe", "could I have a wipe"); after a thing or "it"
  ("give the desk a wipe", "give it a wipe") it is the act, not the office's wipes; before a
  unit it is still the item ("a wipe pack").

Only words no other name of the office reads are read so: a singular that is already a name
of the office (a person, place, facility, another item, a task word) keeps that reading. But
a singular of several words holds a shorter item's name whole as the plural does ("a *scalpel
blade*" where a scalpel is another item, as "scalpel blades" is read whole, longest first):
the longer name is the thing said, word by word its lemmas, not the scalpel and a stray
"blade".
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

UNITS = english.words("unit_nouns")
_OF = "of"
# what stands before a counted noun: an article, a number word, a possessive
_COUNTED_BEFORE = english.words("object_starts") | frozenset({"one", "another", "any", "each"})
# the mention kinds a singular may replace: words the lexicon read as nothing of the office,
# and the pronoun "it" of "post-it"
_PLAIN = frozenset({"word", "pronoun"})
# A counted noun that is also a verb is the thing where it is asked for: after its article,
# after the one it is for (a person, "me") or a verb of asking or having
_ARTICLES = frozenset({"a", "an", "one", "another", "any"})
_ASKING_KINDS = frozenset({"person", "cue"})
_ASKING_WORDS = (
    english.words("self_taking_verbs")
    | english.words("possession_verbs")
    | english.words("need_verbs")
    | english.words("wish_verbs")
)
_OWNING = frozenset({"my", "mine"})


def singulars(names: Iterable[tuple[str, str]], known: Callable[[str], bool]) -> dict[str, str]:
    """The singular phrase of each plural name (key, type id) that no name of the office
    reads already: "post it" for "post its", "bin bag" for "bin bags"."""
    found: dict[str, str] = {}
    for key, type_id in names:
        *head, last = key.split()
        if not language.is_plural_noun(key) and not last.endswith("s"):
            continue
        for one in _singular_words(last):
            phrase = " ".join((*head, one))
            if phrase != key and language.plural(phrase) == key and not known(phrase):
                found.setdefault(phrase, type_id)
    return found


def _singular_words(word: str) -> list[str]:
    """The nouns ``word`` may be the plural of: the dictionary's, then "-s" dropped ("its":
    the pronoun "it" is no noun the dictionary inflects)."""
    out = [w for w in language.lemmas(word).get("NOUN", ()) if w != word]
    if word.endswith("es"):
        out.append(word[:-2])
    if word.endswith("s") and not word.endswith("ss"):
        out.append(word[:-1])
    return out


def singular_spans(
    tokens: Sequence[Token],
    kinds: Mapping[int, str],
    found: Mapping[str, str],
    longest: int,
    items: Mapping[int, tuple[int, int]] | None = None,
) -> list[tuple[int, int, str]]:
    """The (start, end, type id) of each singular of a plural name said where a counted noun
    stands; ``kinds``: the mention kind the lexicon read at each token; ``items``: the span
    of the item mention at each token read as one."""
    out: list[tuple[int, int, str]] = []
    starts = {phrase.split(" ", 1)[0] for phrase in found}  # a name begins only there
    i = 0
    while i < len(tokens):
        span = (
            _singular_at(tokens, kinds, found, longest, i, items or {})
            if tokens[i].word in starts
            else None
        )
        if span is None:
            i += 1
            continue
        out.append(span)
        i = span[1]
    return out


def _singular_at(
    tokens: Sequence[Token],
    kinds: Mapping[int, str],
    found: Mapping[str, str],
    longest: int,
    i: int,
    items: Mapping[int, tuple[int, int]],
) -> tuple[int, int, str] | None:
    for n in range(min(longest, len(tokens) - i), 0, -1):
        end = i + n
        if any(not _free(kinds, items, k, i, end) for k in range(i, end)):
            continue
        if any(tokens[k].opens or tokens[k].after_pause for k in range(i + 1, end)):
            continue  # "post. It ...": no one name across a break
        phrase = " ".join(t.word for t in tokens[i:end])
        type_id = found.get(phrase)
        if type_id is None:
            continue
        before_unit = end < len(tokens) and tokens[end].word in UNITS
        counted = i > 0 and tokens[i - 1].word in _COUNTED_BEFORE
        if before_unit or (counted and (n > 1 or not language.verb_lemmas(phrase))):
            return i, end, type_id
        if counted and _asked_for(tokens, kinds, i - 1):
            return i, end, type_id  # "bring me a wipe": the thing, not the act
    return None


def _free(
    kinds: Mapping[int, str], items: Mapping[int, tuple[int, int]], k: int, start: int, end: int
) -> bool:
    """Whether token ``k`` may be read as part of a singular spanning ``start``-``end``: a
    word no name of the office reads, or a word of a shorter item's name said whole inside a
    singular of several words ("scalpel" of "a scalpel blade")."""
    if kinds.get(k) in _PLAIN:
        return True
    span = items.get(k)
    return (
        end - start > 1
        and kinds.get(k) == "item"
        and span is not None
        and start <= span[0]
        and span[1] <= end
    )


def _asked_for(tokens: Sequence[Token], kinds: Mapping[int, str], article: int) -> bool:
    """Whether a noun that is also a verb, after the article at ``article``, is a thing asked
    for: an article ("a", never "my") right after the one it is for ("bring *me* a wipe",
    "hand *Zhang* a wipe") or after a verb of asking or taking ("I need a wipe", "could I
    *have* a wipe", "anyone *got* a wipe?"). After a thing ("give *the desk* a wipe") or
    "it" ("give it a wipe") the noun is the act done to it (a light verb's object), left
    alone."""
    if article == 0 or tokens[article].word not in _ARTICLES or tokens[article].after_pause:
        return False
    before = article - 1
    if kinds.get(before) == "self":
        return not tokens[before].possessive and tokens[before].word not in _OWNING
    return kinds.get(before) in _ASKING_KINDS or tokens[before].word in _ASKING_WORDS


def unit_of(tokens: Sequence[Token], start: int) -> bool:
    """Whether a unit noun and "of" stand at ``start`` ("a *box of* staples")."""
    return (
        start + 1 < len(tokens)
        and tokens[start].word in UNITS
        and tokens[start + 1].word == _OF
        and not tokens[start + 1].after_pause
    )
