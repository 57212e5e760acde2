"""The speaker's own plan, told: "might heat my soup a bit later", "probably gonna grab a coffee
after the call", "think I'll print my slides tomorrow", "I might eat lunch outside". Its
subject is the speaker (said, or left out, as a diary's is), a helping word of the speaker's
plan stands before the verb ("might", "gonna", "probably", or "I'll" after a thought verb:
"think I'll ..."), and nothing in it is turned to the robot: no "you", no "me" or "us" as
whom it is done for, no "please", no question. It asks nothing: noted, nothing done.

"might you heat my soup", "could you heat my soup", "maybe heat my soup" (a softened command)
and "gonna need a coffee" (a need put off, ``future_need``) are no plan of the speaker's. The
words are English's (``data/english.yaml``); nothing here knows an office."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english, language

_OPENERS = english.words("speech_openers")
_THOUGHTS = english.words("intention_thoughts")
_SUBJECTS = english.words("intention_subjects")
_HELPERS = english.words("intention_helpers")
_HEDGES = english.words("intention_hedges")
_NEED = english.words("need_verbs")
# the words that turn a piece to the robot, or to whom it is done for: a request's
_ADDRESSED = frozenset({"you", "u", "ya", "me", "us", "your"}) | english.words("polite")


def planned_verb(words: list[str]) -> int | None:
    """Where the verb of a plan the words tell of the speaker stands, if they tell one."""
    n = 0
    while n < len(words) and words[n] in _OPENERS:
        n += 1
    thought = False
    if words[n : n + 1] == ["i"] and words[n + 1 : n + 2] and words[n + 1] in _THOUGHTS:
        n += 1  # "I think I'll ..."
    if n < len(words) and words[n] in _THOUGHTS:
        thought, n = True, n + 1
    if n < len(words) and words[n] in _SUBJECTS:
        n += 1
    start = n
    while n < len(words) and words[n] in _HELPERS:
        if words[n] == "going":
            if words[n + 1 : n + 2] != ["to"]:
                break  # "going up the tower later": a doing, no helper
            n += 1  # "going to": one helper
        n += 1
    helpers = set(words[start:n])
    if not helpers or not (thought or helpers & _HEDGES):
        return None  # no helper, or a bare "I'll" ("I'll have a tea"): may be an order
    if n >= len(words):
        return None
    verb = words[n]
    if verb in _NEED or verb in _HELPERS or verb not in language.verb_lemmas(verb):
        return None  # "gonna need ...": a need put off (``future_need``), not a plan
    return n


def own_intention(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    del terms, msg, requester
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.question is not None:
        return None
    words = piece.words
    if planned_verb(words) is None or set(words) & _ADDRESSED:
        return None
    return Finding("statement", piece, "the speaker's own plan, told: context only")
