"""Condition: "if Hal ever needs a ruler, Ida has one", "when I'm back, ...": says when,
never what to do; a need that may come later is not a request for now."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.rewrites import purposes
from assistantx.agents.symbolic.reading.screen.statement import stated_items
from assistantx.agents.symbolic.reading.screen.terms import Terms, article
from assistantx.core.english import words as english_words

# "a new one", "another", "a replacement": a need that replaces an item said to be failing.
_REPLACEMENT = english_words("replacement_words")
_CONDITION_WORDS = english_words("condition_openers")
_NEED = english_words("need_verbs")
# What makes the need only possible: "might", "probably", "I think", "I'll".
_HEDGES = english_words("possibility_words") | frozenset({"think", "guess", "ill", "will"})


def condition(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """ "if Hal ever needs a ruler, Ida has one": a condition says when, never what to do;
    with no request beside it the message is information, answered in words."""
    put_off = piece.acts.defers and not piece.acts.imperative
    if not put_off:
        offered = _replacement_offer(terms, msg, piece)
        if offered is not None:
            return offered
    if put_off or piece.acts.future_need:
        return Finding(
            "condition",
            piece,
            "a need that may come later, not a request for now",
            message="Noted. Tell me when you need it and I'll bring it then.",
            # "need something to peg out the boundary with tomorrow, can you bring me some":
            # a request beside it for now means the thing needed, said or described
            context=(*stated_items(terms, piece, requester), *_described(terms, piece)),
        )
    if not piece.acts.condition:
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


def _described(terms: Terms, piece: Piece) -> tuple[str, ...]:
    """The one item a piece says by its purpose ("something to peg out the boundary with"),
    as a context entry: the piece read again with the purpose said as that item's name; none
    where it names none or several."""
    described, found = purposes(terms, piece.text)
    if not found:
        return ()
    items = terms.named(terms.lex.read(described), "item")
    return (f"{items[0]}|",) if len(items) == 1 else ()


def _replacement_offer(terms: Terms, msg: Message, piece: Piece) -> Finding | None:
    """ "my tripod is wobbly, I might need a new one": a possible need of a replacement for
    an item said to be failing, with no condition and no "later", is offered ("Shall I bring
    you a tripod?"), never fetched at once nor only noted."""
    words = set(piece.words)
    if not (words & _NEED and words & _HEDGES and words & _REPLACEMENT):
        return None
    if words & _CONDITION_WORDS or piece.acts.later:
        return None
    before = (i for p in msg.pieces if p.end <= piece.start for i in terms.named(p.lexed, "item"))
    said = terms.named(piece.lexed, "item") or list(dict.fromkeys(before))[-1:]
    if len(said) != 1:
        return None
    t = terms.office.item_type(said[0])
    if t.kind not in ("belonging", "product"):
        return None
    verb = "get" if t.kind == "product" else "bring"
    thing = f"{article(t.name)} {t.name}"
    return Finding(
        "condition",
        piece,
        f"a possible need of a new {t.name}: offered, not fetched",
        message=f"Sorry about your {t.name}.",
        offer=f"{verb} me {thing}",
        shall=f"Shall I {verb} you {thing}?",
        context=(f"{said[0]}|",),  # "..., can you bring one?": the one is this item
    )
