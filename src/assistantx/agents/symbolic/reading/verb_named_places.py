"""A place of the office whose one-word name is also one of its services' verbs ("Dispatch"
where a courier desk "dispatches", "Print" where the printer prints): the lexicon keeps such a
word a verb ("dispatch my contract to Acme"), so a bare "dispatch" asks for the service; said
where English names a place, after a preposition of where something or someone is ("Mateus
*in* dispatch", "the stapler *from* dispatch", "*at* the Print"), it is the place, never the
service. The office's own locations say which words these are; nothing is listed here."""

from __future__ import annotations

from collections.abc import Collection, Iterable, Sequence

from assistantx.agents.symbolic.reading.tokens import Token

# The prepositions of where a thing or a person is, or where a thing is taken from: a word
# after them names a place ("with Mateus in dispatch", "from dispatch"). "to" is left out:
# "to dispatch" is also the infinitive of the verb ("I need you to dispatch it").
_WHERE = frozenset({"in", "at", "inside", "from", "near", "by"})
# Skipped between the preposition and the name ("in the dispatch"): the name may take one.
_ARTICLES = frozenset({"the", "our", "that"})


def verb_named_places(names: Iterable[tuple[str, str]], verbs: Collection[str]) -> dict[str, str]:
    """The one-word names among ``names`` (key, location id) that are also a service verb of
    ``verbs``: the places the lexicon reads as a place only in a place's slot."""
    return {key: loc for key, loc in names if key and " " not in key and key in verbs}


def clipped_verb_places(names: Iterable[tuple[str, str]], verbs: Collection[str]) -> dict[str, str]:
    """The two-word names among ``names`` whose first word alone is a service verb of
    ``verbs``: people leave the kind of place out ("Mateus in dispatch" of the "Dispatch
    room"). Read as the place only after a preposition of where other than "by": "by post"
    of a "Post room" is still the means ("send it to Cardiff by post")."""
    found: dict[str, str] = {}
    for key, loc in names:
        words = key.split()
        if len(words) == 2 and words[0] in verbs:
            found.setdefault(words[0], loc)
    return found


def in_a_place_slot(tokens: Sequence[Token], i: int, *, by_too: bool = True) -> bool:
    """Whether token ``i`` stands where English names a place: after a preposition of where
    (an article between allowed), or after "out of"; after "by" only when ``by_too``."""
    k = i - 1
    while k >= 0 and tokens[k].word in _ARTICLES:
        k -= 1
    if k < 0:
        return False
    before = tokens[k].word
    out_of = before == "of" and k >= 1 and tokens[k - 1].word == "out"
    return (before in _WHERE and (by_too or before != "by")) or out_of
