"""A machine asked for in a kind the office does not have: "fire my jug in the raku kiln"
where the office has one plain kiln, "heat my lunch in the gas microwave".

The lexicon reads the office's machine word ("kiln") and the frames run the office's one,
dropping the words that asked for another kind of it: a wrong physical action. The screen
reads the words right before a facility's name in a request (after its determiner,
possessive or preposition) as ``variant`` reads them before a product's name, and a word that
names a kind of machine makes the request a question: "There's no raku kiln here, only the
kiln. Shall I use the kiln instead?", a yes reading the request without those words.

A kind's word: one the dictionary does not know ("raku", "wood-fired", "A3"), or a noun with
no adjective reading ("gas", "espresso", "colour"). Never one: a word of the facility's own
names or synonyms, or of any name of the office (a room's: "the studio kiln"); a word that
says which one stands where or who shares it (english.yaml ``machine_which_words``,
``place_words``, ``place_heads``, ``outside_workplaces``: "the office printer", "the kitchen
microwave"); an adjective ("the big printer", "the new printer", "the usual printer"); a
possessive ("Ana's kiln"); anything after the name ("the printer downstairs"). A name written
capitalised throughout ("the County Dairy Lab") is a place's proper name. A facility's
name that modifies a noun after it ("colour printer paper") names no machine asked for.
"""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.screen.variant import (
    MOST_MODIFIERS,
    OFFICE_KINDS,
    modifier,
    span_of,
)
from assistantx.agents.symbolic.reading.tokens import Token, gaps
from assistantx.core import english, language
from assistantx.core.office import Office

_WHICH_ONE = (
    english.words("machine_which_words")
    | english.words("place_words")
    | english.words("place_heads")
    | english.words("outside_workplaces")
)
# what the modifiers follow: a determiner or a preposition ("in *the* raku kiln", "on A3 ...")
_OPENERS = (
    english.words("determiners")
    | english.words("location_prepositions")
    | english.words("instrument_prepositions")
    | english.words("to_facility_prepositions")
    | english.words("from_facility_prepositions")
) - {"me", "you", "him", "her", "us", "them"}
# what opens the next phrase after a machine's name ("the raku kiln *this* afternoon")
_NOT_A_HEAD = (
    english.words("time_nouns")
    | english.words("determiners")
    | english.words("screen_determiners")
    | english.words("pronouns")
)


def facility_variant(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """The screen's rule: a request piece naming a kind of machine the office does not have."""
    del requester  # the earlier rules of the table took the pieces that ask nothing
    found = _facility_variant(terms, piece)
    if found is None:
        return None
    mention, said = found
    place = terms.office.facility(mention.ids[0])
    where = span_of(msg, piece, said)
    if where is None:
        return None
    asked = msg.text[where[0] : where[1]]
    # the machine as it was asked for ("pizza oven"), not by the office's name for it
    named = span_of(msg, piece, piece.lexed.tokens[mention.start : mention.end])
    machine = msg.text[named[0] : named[1]] if named is not None else place.name
    own = f"the {place.name}"
    offer = f"{msg.text[: where[0]]}{msg.text[where[1] :].lstrip()}"
    return Finding(
        "instead",
        piece,
        f"a kind of machine the office does not have: {asked} {machine}",
        message=(f"There's no {asked} {machine} here, only {own}. Shall I use {own} instead?"),
        offer=offer,
    )


def _facility_variant(terms: Terms, piece: Piece) -> tuple[Mention, tuple[Token, ...]] | None:
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    office_at = {k for m in mentions if m.kind in OFFICE_KINDS for k in range(m.start, m.end)}
    breaks = gaps(piece.text, tokens)
    for m in mentions:
        if m.kind != "facility" or len(set(m.ids)) != 1:
            continue
        if _modifies_a_noun(tokens, breaks, office_at, m):
            continue  # "colour printer paper": the paper, no machine asked for
        start, hyphened = m.start, False
        while start > 0 and m.start - start < MOST_MODIFIERS and not breaks[start].strip():
            before = _word_before(terms, tokens, breaks, office_at, start)
            if before is None:
                break
            hyphened = hyphened or before < start - 1
            start = before
        said = tokens[start : m.start]
        if not said or _proper_name(tokens[start : m.end]):
            continue
        if start == 0 or tokens[start - 1].word not in _OPENERS:
            continue  # "can you book lounge for 3pm": the verb asked, no kind of lounge
        own = _own_words(terms.office, m.ids[0]) | terms.office_words
        if all(t.word in own for t in said) if hyphened else any(t.word in own for t in said):
            continue  # "the big electric kiln": a word of the office's own names
        if hyphened or any(_names_a_kind(t.word) for t in said):
            return m, said
    return None


def _word_before(
    terms: Terms,
    tokens: tuple[Token, ...],
    breaks: tuple[str, ...],
    office_at: set[int],
    start: int,
) -> int | None:
    """Where the modifier just before ``start`` begins: a word a modifier may be, or a
    compound written with hyphens ("wood-fired", "A3-size"), whatever its parts are; None
    where the words before the name stop."""
    at = start - 1
    first = at
    while first > 0 and breaks[first].strip() == "-":
        first -= 1
    if first < at:
        return first  # a service's verb inside a compound ("wood-fired") is no request
    if at in office_at:
        return None
    return at if modifier(terms, tokens[at], first=at == 0) else None


def _proper_name(words: tuple[Token, ...]) -> bool:
    """Whether the modifiers and the machine's word are all written capitalised ("to the
    County Dairy Lab on Mallow Road"): a place's proper name, no machine asked for."""
    return all(t.text[:1].isupper() for t in words)


def _own_words(office: Office, facility_id: str) -> frozenset[str]:
    place = office.facility(facility_id)
    return frozenset(
        w for name in (place.name, *place.synonyms) for w in language.words(language.fold(name))
    )


def _modifies_a_noun(
    tokens: tuple[Token, ...], breaks: tuple[str, ...], office_at: set[int], m: Mention
) -> bool:
    if m.end >= len(tokens) or breaks[m.end].strip():
        return False
    after = tokens[m.end].word
    if m.end in office_at:
        return True
    if after in _NOT_A_HEAD:
        return False  # "the raku kiln this afternoon"
    return set(language.lemmas(after)) == {"NOUN"}


def _names_a_kind(word: str) -> bool:
    """A kind of machine: a word the dictionary does not know ("raku"), or a noun with no
    adjective reading ("gas"); never a word of which one ("office", "kitchen")."""
    if word in _WHICH_ONE or word.isdigit():
        return False
    read = language.lemmas(word)
    if not read:
        return True
    return "NOUN" in read and "ADJ" not in read
