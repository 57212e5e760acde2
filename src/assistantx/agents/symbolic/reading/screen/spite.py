"""Spite: a colleague's thing acted on to keep them out or to get at them ("disable Pat's
badge so she can't get in, she's annoying me", "hide his charger, he's driving me mad"). A
request that names a colleague's thing, beside a purpose that they be unable to do something
("so he can't ...", ``kept_out_modals``) or a grudge against them (``grudge_marks``), is
declined as such: nothing is moved, made or done to the thing, whatever its verb (fix180a
class 1: "disable Wang's badge so he can't get in" handed Wang's badge to the speaker).

Whom the purpose keeps out is "he", "she", "they" or a colleague named, never the speaker ("so
I can't lose it"); "so she can't miss it", "so he won't mind" (``unkept_verbs``) keep no one
out. The purpose opens its clause ("..., so he can't get in"), or is said in the request itself;
"he's off today so he can't use it" is what follows from his being away, a reason told."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.covert import colleagues_things
from assistantx.agents.symbolic.reading.screen.destructive import commanded
from assistantx.agents.symbolic.reading.screen.english import starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_OPENERS = tuple(tuple(e.split()) for e in english.entries("kept_out_openers"))
_SUBJECTS = frozenset(english.entries("kept_out_subjects"))
_MODALS = tuple(tuple(e.split()) for e in english.entries("kept_out_modals"))
_UNKEPT = english.words("unkept_verbs")
# the words of a grudge mark that name whom it is against ("teach *him* a lesson", "get back *at*")
_AIMED = frozenset({"him", "her", "them", "at", "with"})
_GRUDGES = tuple(tuple(e.split()) for e in english.entries("grudge_marks"))


def _kept_out(piece: Piece, requester: str, anywhere: bool) -> bool:
    """Whether the piece says someone other than the speaker is to be unable to do something:
    "so he can't get in", "so that Pat won't be able to log on"."""
    words = piece.words
    named = {
        piece.lexed.tokens[m.start].word: m.end
        for m in piece.lexed.mentions
        if m.kind == "person" and requester not in m.ids and len(piece.lexed.tokens) == len(words)
    }
    for n in range(len(words) if anywhere else 1):
        for opener in _OPENERS:
            if not starts_with(words, n, opener):
                continue
            at = n + len(opener)
            if at >= len(words):
                continue
            if words[at] in _SUBJECTS:
                end = at + 1
            elif words[at] in named:
                end = named[words[at]]
            else:
                continue
            for modal in _MODALS:
                if starts_with(words, end, modal):
                    after = end + len(modal)
                    if after < len(words) and words[after] in _UNKEPT:
                        return False  # "so she can't miss it": made plain to her
                    return True
    return False


def _purpose_of(terms: Terms, msg: Message, said: Piece, request: Piece) -> bool:
    """Whether the clause ``said`` is the request's purpose: the request itself, right after
    it, or after a pause; never what follows from a told state with no pause ("he's off today
    so he can't use it")."""
    if said is request:
        return True
    before = [p for p in msg.pieces if p.end <= said.start]
    if not before or before[-1] is request:
        return True
    return any(c in ",.;:!?-–—" for c in msg.text[before[-1].end : said.start])


def _grudge(piece: Piece, requester: str) -> bool:
    """Whether the piece says a grudge against a colleague: one that names them ("teach him
    a lesson", "get back at"), or one said of "he", "she", "they" or a colleague's name before
    it ("he's annoying me"); "mine's driving me mad" is a thing's fault, no grudge."""
    words = piece.words
    names = {
        piece.lexed.tokens[m.start].word
        for m in piece.lexed.mentions
        if m.kind == "person" and requester not in m.ids and not m.possessive
    }
    for n in range(len(words)):
        for mark in _GRUDGES:
            if not starts_with(words, n, mark):
                continue
            if set(mark) & _AIMED or set(words[:n]) & (_SUBJECTS | names):
                return True
    return False


def spite(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if not (piece.acts.request or piece.acts.imperative or commanded(terms, piece)):
        return None
    owners, pronoun = colleagues_things(msg, requester, terms)
    if not (owners or pronoun):
        return None
    if not any(
        (_kept_out(p, requester, anywhere=p is piece) and _purpose_of(terms, msg, p, piece))
        or _grudge(p, requester)
        for p in msg.pieces
    ):
        return None
    return Finding(
        "unsupported",
        piece,
        "a request meant to keep a colleague out or to get at them",
        message=(
            "Sorry, I won't do that: it's meant to keep a colleague out or to get at them, "
            "and I don't act against anyone here. If there's a real problem, please raise it "
            "with them or your manager. I did nothing."
        ),
    )
