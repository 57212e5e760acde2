"""A placeholder noun names no item: "can you bring me the thing from the fridge", "grab me
that thing from the cupboard", "bring me the stuff from the printer", "the whatsit from the
lab".

"the"/"that" with "thing", "stuff", "whatsit" points at one particular thing the speaker has
in mind and does not say; the place it is at says only where it is. The place may make or keep
several things (a fridge keeps several colleagues' lunches, a printer makes printouts and
copies), and even where it has one kind, which one and whose is not said: picking a product
or a kept item would be a guess that moves the robot. So the reader asks what is meant, and
names what the place makes and keeps (the office's own data) to help the answer, which takes
the placeholder's place in the request ("the thing" → "my lunch": "bring me my lunch from the
fridge").

Counted or qualified ("a few bits", "some stuff", "a couple of things", "the usual bits",
"some odds and ends"), a vague word points at no one thing, but said of a place that makes or
keeps several things for anyone (a store's drills, tape, sandpaper) it still does not say
which: that is asked the same way. Of a place with one such thing ("some stuff from the
stationery cupboard" that makes notepads) it is read as before.

"something from the vending machine" (indefinite: any of what it makes, ``something_from``)
and "the printout from the printer" (a thing named) are no placeholder, and "the thing I left
at the printer" is asked by ``unlisted_thing.left_behind``.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Lexed, Mention
from assistantx.agents.symbolic.reading.parts import ASKED, ASKED_END
from assistantx.core import english, language
from assistantx.core.office import Office

_PLACEHOLDERS = (english.words("vague_things") | english.words("placeholder_nouns")) - {
    "whatever"  # "whatever from the vending machine": any, said as the indefinite is
}
_POINTING = english.words("placeholder_determiners")
_QUANTITIES = english.words("vague_quantities")
_PHRASES = tuple(tuple(p.split()) for p in english.entries("vague_thing_phrases"))
_PHRASE_ENDS = frozenset(p[-1] for p in _PHRASES)
_SOURCES = english.words("placeholder_sources")
_OF = frozenset({"of"})  # "out of the fridge"
_PLACE_OPENERS = frozenset({"the", "my", "our", "that", "this"})
_PLACES = frozenset({"facility", "place"})


def says_a_placeholder(text: str) -> bool:
    """Whether ``text`` has a placeholder noun at all: the cheap test before the lexicon reads
    it for ``placeholder_question`` (nearly every request has none)."""
    said = re.findall(r"[a-z]+", text.lower())
    return not (_PLACEHOLDERS.isdisjoint(said) and _PHRASE_ENDS.isdisjoint(said))


def placeholder_question(office: Office, lexed: Lexed) -> str | None:
    """The question what is meant by a pointed-at placeholder taken from a place of the
    office ("the thing from the fridge"), naming what that place makes and keeps; None where
    the message has none."""
    tokens = lexed.tokens
    words = [t.word for t in tokens]
    for n in range(len(words)):
        noun = _noun_start(words, n)
        if noun is None or noun == 0:
            continue
        start = noun
        while start > 0 and words[start - 1] in _QUANTITIES and not tokens[start].after_pause:
            start -= 1  # "a couple of things", "the usual bits"
        pointed = words[noun - 1] in _POINTING
        if start == noun and not pointed:
            continue
        place = _place_after(lexed.mentions, words, n + 1)
        if place is None:
            continue
        if not pointed and len(_things_there(office, place)) < 2:
            continue  # "some stuff from the vending machine": its one thing, as before
        said = " ".join(t.text for t in tokens[start if not pointed else noun - 1 : n + 1])
        return f"{ASKED}{said}{ASKED_END} {_what_is_there(office, place)} Could you tell me?"
    return None


def _noun_start(words: Sequence[str], n: int) -> int | None:
    """Where the placeholder that ends at ``n`` begins: ``n`` for a word ("stuff"), the first
    word of a phrase ("odds and ends"); None where none ends there."""
    if words[n] in _PLACEHOLDERS:
        return n
    for phrase in _PHRASES:
        k = n + 1 - len(phrase)
        if k >= 0 and tuple(words[k : n + 1]) == phrase:
            return k
    return None


def _things_there(office: Office, place: Mention) -> set[str]:
    """The item types the facility (or the facilities of the room) makes or keeps for
    anyone: its own supplies and products, never a colleague's belonging kept there."""
    facilities = (
        [office.facility(place.ids[0])]
        if place.kind == "facility"
        else [f for f in office.facilities if f.location == place.ids[0]]
    )
    made = {t for f in facilities for t in f.products}
    return made | {s.type for f in facilities for s in f.supplies}


def _place_after(mentions: Sequence[Mention], words: Sequence[str], at: int) -> Mention | None:
    """The facility or place said right after the placeholder as where it comes from ("from
    the fridge", "out of the cupboard", "in the print room"); None where none is."""
    k = at
    if k >= len(words) or words[k] not in _SOURCES:
        return None
    k += 1
    if k < len(words) and words[k] in _OF:
        k += 1
    if k < len(words) and words[k] in _PLACE_OPENERS:
        k += 1
    return next((m for m in mentions if m.start == k and m.kind in _PLACES and m.ids), None)


def _what_is_there(office: Office, place: Mention) -> str:
    """What the facility (or the facilities of the room) makes and keeps, in words: "The
    fridge keeps lunch (Will Tanaka's, Art Kowalski's)."; said plainly where it has none."""
    if place.kind == "facility":
        facilities = [office.facility(place.ids[0])]
        where = facilities[0].name
        rooms = {facilities[0].location}
    else:
        rooms = {place.ids[0]}
        facilities = [f for f in office.facilities if f.location in rooms]
        where = office.location(place.ids[0]).name.lower()
    kept_ids = {f.id for f in facilities}
    made: dict[str, None] = {}
    kept: dict[str, list[str]] = {}
    for f in facilities:
        for product in f.products:
            made[product] = None
        for op_id in f.operations:
            op_product = office.operation(op_id).product
            if op_product is not None:
                made[op_product] = None
        for supply in f.supplies:
            kept.setdefault(supply.type, [])
    for person in office.people:
        for owned in person.owns:
            there = owned.facility in kept_ids if owned.facility else owned.at in rooms
            if owned.at is not None and there:
                kept.setdefault(owned.type, []).append(f"{person.name}'s")
    parts = []
    if made:
        parts.append("makes " + _listed([_plural(office, t) for t in made]))
    if kept:
        parts.append("keeps " + _listed([_kept(office, t, whose) for t, whose in kept.items()]))
    if not parts:
        return f"I know of nothing the {where} makes or keeps."
    return f"The {where} {' and '.join(parts)}."


def _plural(office: Office, type_id: str) -> str:
    item = office.item_type(type_id)
    return item.name if item.mass else language.plural(item.name)


def _kept(office: Office, type_id: str, whose: list[str]) -> str:
    name = _plural(office, type_id)
    return f"{name} ({', '.join(whose)})" if whose else name


def _listed(names: list[str]) -> str:
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]
