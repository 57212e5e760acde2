"""On a thing: "oil on the stapler again", "Olive oil on the velvet AGAIN", "glue all over my
scissors", "crumbs in the printer tray": a fragment with no verb and no request wording that
says something is on, in or over a thing of the office is a remark about that thing, told,
never a request for it. It had fetched the thing it named (someone's fabric, a stapler): a
bare fragment is read as asking for what it names first, and here that is the oil.

Only where a word that names no item of the office comes before the preposition, and every
item the piece names comes after one: "the stapler on my desk please" (the thing first),
"paper in the printer" and "some twine from the potting shed" are read as before, as is any
piece with request wording, a question mark or a verb, or said "for me" (something done for
the speaker is asked, whatever its verb: "bypass the lock on this phone for me")."""

from __future__ import annotations

import itertools

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import english, language
from assistantx.core.receiving_place import PLACE_WORDS

# where one thing lies on another ("on", "all over", "in"); "from"/"for"/"to" say where a
# thing comes from or goes, and stay requests
_ON = frozenset({"on", "over", "in", "inside", "under", "across", "onto", "into"})
# what a remark on a thing may name besides the thing
_TOLD = frozenset({"item", "person", "word", "self", "pronoun"})
# "everywhere": a thing said to be spread so is a mess ("all over" too)
_EVERYWHERE = frozenset({"everywhere"})
# words that ask, however short the fragment ("stapler on my desk pls"), and haste
_ASKING = english.words("asking_words") | frozenset({"quick", "quickly"})
# whom a thing done for the speaker is for ("... for me"): a remark is for nobody
_FOR_SPEAKER = frozenset({"me", "us"})
# asides that join a second part to the errand before it ("on the way back")
_ASIDES = tuple(tuple(p.split()) for p in english.entries("request_asides"))


def on_a_thing(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.question is not None:
        return None
    if acts.need or acts.wish or acts.note is not None or acts.condition:
        return None
    words = content(piece.words)
    if not words or set(words) & _ASKING:
        return None
    if any(a == "for" and b in _FOR_SPEAKER for a, b in itertools.pairwise(words)):
        return None  # "bypass the lock on this phone for me": done for the speaker, asked
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    items = [m for m in mentions if m.kind in ("item", "cue")]
    if not items:
        return None
    said = [t.word for t in tokens]
    if _mess(said, items) and all(m.kind in _TOLD or m.kind == "cue" for m in mentions):
        # "red wax all over the floor": an operation's word ("wax") is the mess's thing too
        return Finding("statement", piece, "a remark about a mess, asking nothing")
    if any(m.kind not in _TOLD for m in mentions):
        return None
    at = next((k for k, t in enumerate(tokens) if k and t.word in _ON), None)
    if at is None or _aside_at(said, at):
        return None
    before = said[:at]
    if any(m.start < at for m in items):
        # "the stapler on my desk": the thing said first is asked for, brought there;
        # "coffee on my keyboard again": on something that is no place, it was spilt
        return _spilt(piece, at) if items[0].start < at and not _after(items, at) else None
    if any(language.is_finite_verb(w) and not language.is_noun(w) for w in before):
        return None  # "put oil on the stapler": a verb, read by the rules for it
    if not any(language.is_noun(w) for w in before):
        return None
    return Finding("statement", piece, "a remark about something on a thing, asking nothing")


# where a thing asked for may be left: "coffee on my desk", "paper on the shelf"
_RECEIVING = (PLACE_WORDS | english.words("surface_words")) - {"floor"}  # no one asks for the floor
_WHOSE = frozenset({"my", "our", "the", "his", "her", "their", "your", "a", "this", "that"})


def _aside_at(said: list[str], at: int) -> bool:
    """ "a coffee for me on the way back", "... on your way past": the "on" opens an aside
    that joins the piece to the errand before it (``request_asides``), the way no surface
    anything was spilt on: the piece asks for its thing as a second part."""
    return any(tuple(said[at : at + len(p)]) == p for p in _ASIDES)


def _mess(said: list[str], items: list[Mention]) -> bool:
    """ "red wax all over the floor", "glitter everywhere again": a thing named, then said to be
    spread over anything or everywhere: a mess told, never where to take it."""
    for k, word in enumerate(said):
        spread = word in _EVERYWHERE or (word == "over" and k and said[k - 1] == "all")
        if spread and k and all(m.start < k - (word == "over") for m in items):
            return True
    return False


def _after(items: list[Mention], at: int) -> bool:
    return any(m.start > at for m in items)


def _spilt(piece: Piece, at: int) -> Finding | None:
    """ "coffee on my keyboard again": the thing first, then on a plain noun that is no place
    to leave it (no desk, shelf or tray, no place or facility of the office), and nothing
    else: a mess told, not a request to bring the thing there."""
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    after = [m for m in mentions if m.start > at]
    if any(m.kind not in ("word", "self") for m in after):
        return None  # a person, a place, a facility: where to take it
    rest = [t.word for t in tokens[at + 1 :]]
    while rest and rest[0] in _WHOSE:
        rest = rest[1:]
    if not rest or rest[0] in _RECEIVING or not language.is_noun(rest[0]):
        return None
    return Finding("statement", piece, "a remark about something spilt on a thing, asking nothing")
