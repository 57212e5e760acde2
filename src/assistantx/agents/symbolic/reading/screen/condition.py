"""Condition: "if Hal ever needs a ruler, Ida has one", "when I'm back, ...": says when,
never what to do; a need that may come later is not a request for now."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import split_words
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.statement import stated_items
from assistantx.agents.symbolic.reading.screen.terms import Terms


def condition(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """ "if Hal ever needs a ruler, Ida has one": a condition says when, never what to do;
    with no request beside it the message is information, answered in words."""
    deferred = terms.acts.defers(split_words(msg.text))
    put_off = terms.acts.defers(piece.words) and not terms.acts.imperative(piece.words)
    if put_off or terms.acts.future_need(piece.words, deferred):
        return Finding(
            "condition",
            piece,
            "a need that may come later, not a request for now",
            message="Noted. Tell me when you need it and I'll bring it then.",
        )
    if not terms.acts.condition(piece.words, piece.asks):
        return None
    # what the condition names is context for a request beside it, as a statement's is:
    # "if Hedda isn't using her laser, could you bring it over?" asks for Hedda's laser
    named = tuple(stated_items(terms, piece, requester)) + tuple(
        f"person:{p}" for p in terms.named(piece.lexed, "person")[:1]
    )
    return Finding(
        "condition",
        piece,
        "a condition, not a request",
        message="Noted; I'll keep it in mind.",
        context=named,
    )
