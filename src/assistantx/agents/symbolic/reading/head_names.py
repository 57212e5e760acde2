"""A bare noun that is the head of several of one item type's names is that type: "is there
any *gel* going?" where the sanitiser is also called "hand gel" and "alcohol gel".

In English the head of a compound noun is its last word, the words before it say which kind
("hand gel" is a gel); in a name with a preposition it is the last word before it ("pad of
post-its" is a pad). When the office calls one type of thing by two names or more that end in
the same noun, that noun alone is the office's word for the type too, as "the dispenser" is
for "the tape dispenser" once the tape is known (``screen.head_noun_back``). One name alone
ending so ("tape dispenser") says no more than that the thing is a kind of it: a bare
"dispenser" may be any, and keeps its reading (a thing the office does not have).

A head of two types' names ("roller" of a paint roller and a lint roller) is no one type's:
which of them is asked (``unknown_items.category_asked``), never guessed. A head that is
already a word of the office (a name, another type's synonym, a task word), that ends a
facility's or a place's name too ("machine" of "coffee machine"), that is said inside a
facility's, a place's or another type's name ("aid" of "band-aid" where the office has a
"first aid room" and a "first aid bag"), or that is a unit noun ("a *pad*", "a *set*": a unit
of anything) is never read so.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

from assistantx.core import english, language

_UNITS = english.words("unit_nouns") | english.words("portion_words")
_COMMON = english.words("common")
# The prepositions inside a name that end its head ("pad *of* post-its", "drink *from* ...").
_INSIDE = english.words("party_prepositions") | english.words("modifier_prepositions")
_ENOUGH = 2  # names of one type ending in the noun that make it the type's word


def head_of(key: str) -> str:
    """The head noun of a name of several words ("gel" of "hand gel", "pad" of "pad of post
    its", "drink" of "drink from the vending machine"); "" for a name of one word, or one
    whose head is a function word or no word."""
    words = key.split()
    if len(words) < 2:
        return ""
    cut = next((n for n, w in enumerate(words) if n > 0 and w in _INSIDE), len(words))
    head = words[cut - 1]
    return head if head.isalpha() and head not in _COMMON else ""


def _heads(names: Iterable[tuple[str, str]]) -> dict[str, dict[str, int]]:
    """Head noun (singular, as said) → type id → how many of its names end in it."""
    found: dict[str, dict[str, int]] = {}
    for key, type_id in names:
        head = head_of(key)
        if head:
            counted = found.setdefault(_singular(head), {})
            counted[type_id] = counted.get(type_id, 0) + 1
    return found


def _singular(word: str) -> str:
    nouns = [n for n in language.lemmas(word).get("NOUN", ()) if n != word]
    return nouns[0] if nouns and language.plural(nouns[0]) == word else word


def head_names(
    items: Iterable[tuple[str, str]],
    others: Iterable[str],
    known: Callable[[str], bool],
) -> tuple[dict[str, str], dict[str, tuple[str, ...]]]:
    """The heads each of one type (form → type id, singular and plural) and the heads shared
    by several types (singular → their ids, in the office's order). ``items``: (name key,
    type id) of every name and synonym of the office's item types; ``others``: the keys of
    its facilities' and places' names; ``known``: whether a word is already the office's."""
    items = list(items)
    others = list(others)
    taken = {_singular(head) for key in others if (head := head_of(key))}
    # a word inside another name, before its head ("aid" of "first aid bag", "first aid
    # room"): "from first aid" names that place or thing, never "band-aids" by their head
    in_places = {w for key in others for w in key.split()[:-1]}
    inside: set[str] = set()
    one: dict[str, str] = {}
    shared: dict[str, tuple[str, ...]] = {}
    heads = _heads(items)
    for key, type_id in items:
        for w in key.split()[:-1]:
            if heads.get(w) and set(heads[w]) != {type_id}:
                inside.add(w)
    for head, counted in heads.items():
        forms = (head, language.plural(head))
        if head in _UNITS or head in taken or any(known(f) for f in forms):
            continue
        if len(counted) > 1:
            # only ever asked ("which protector: the glass or the hydrogel one?"), so also
            # where a machine's or another thing's name holds it ("protector cutter", "mic
            # cable" beside three mics): a question moves nothing
            shared[head] = tuple(counted)
            continue
        if head in inside or head in in_places:
            continue  # "from first aid": the room's name clipped, never plasters fetched
        ((type_id, names),) = counted.items()
        if names >= _ENOUGH:
            for form in forms:
                one[form] = type_id
    return one, shared


def shared_types(shared: dict[str, tuple[str, ...]], thing: str) -> tuple[str, ...]:
    """The item types a bare noun asked for heads the names of, where it heads two types'
    or more ("a roller": the paint roller and the lint roller); () otherwise."""
    words = thing.split()
    if len(words) != 1:
        return ()
    return shared.get(_singular(words[0]), ())
