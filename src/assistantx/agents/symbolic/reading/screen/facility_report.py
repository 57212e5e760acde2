"""Facility report: "scanner's jammed btw", "the label printer's out of ribbon again, ugh": a
facility of the office said to be in some state, with no request wording and no question.
Answered in words; nothing moves, and the facility's name is never read as its operation's
verb ("scanner" is no "scan this")."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.elsewhere import state_said
from assistantx.agents.symbolic.reading.screen.english import starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_FAULTS = tuple(tuple(p.split()) for p in english.entries("facility_faults"))


def facility_report(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.question is not None:
        return None
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    k = 0
    while k < len(mentions) and mentions[k].kind == "word":
        if tokens[mentions[k].start].word not in terms.en.fact_openers:
            return None
        k += 1
    if k >= len(mentions) or mentions[k].kind != "facility" or len(mentions[k].ids) != 1:
        return None
    subject = mentions[k]
    rest = [t.word for t in tokens[subject.end :]]
    copula = next((c for c in terms.en.copulas if starts_with(rest, 0, c)), None)
    if copula is None and not subject.possessive:
        return None  # "the scanner jammed my strip": told as what it did, read elsewhere
    state = state_said(rest[len(copula) :] if copula else rest)
    if not any(starts_with(state, 0, f) for f in (*terms.en.conditions, *_FAULTS)):
        return None
    name = terms.office.facility(subject.ids[0]).name
    said = " ".join(state)
    return Finding(
        "statement",
        piece,
        f"a report: the {name} is {said}",
        message=f"Thanks for letting me know the {name} is {said}.",
    )
