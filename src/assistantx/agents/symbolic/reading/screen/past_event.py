"""Past event: "need some secateurs, *mine went in the compost*", "need a new folder, *mine got
shredded by mistake*": what already happened to the speaker's own thing, told beside the
request, is why it is made. It is context: a service its words name (the compost, the
shredder) is not asked for, and a waste container it names puts nothing away.

The piece asks for nothing (no request wording, no imperative, no question), names a service,
facility or waste container (any other event is read as before), its subject is
the speaker's own ("mine", "ours", "my old one") and its verb is past ("went", "got
shredded", "was binned", "has been shredded"). Alone it is a statement too; a request after
it that points back to it ("..., can I have a new one") is read as before."""

from __future__ import annotations

from collections.abc import Container

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.purpose import POINTERS
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import english, language

# A subject that is the speaker's own thing by itself ("mine went ...").
_OWN = frozenset({"mine", "ours"})
# A possessive that opens the speaker's own thing ("my old one got ...").
_OWN_OPENERS = frozenset({"my", "our"})
_PERFECT = frozenset({"has", "have", "had"})
_MODALS = english.words("modal_auxiliaries")
_REACH = 4  # the most words of "my ..." before its verb


def past_event(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.question is not None:
        return None
    if acts.need or acts.wish or acts.condition or acts.note is not None:
        return None
    words = content(piece.words)
    verb = _verb_at(words, terms.lex.items)
    if verb is None or not _past(words, verb):
        return None
    if not _names_a_service(terms, piece):
        return None  # "my calculator died, ...": read as before, its thing lent on
    after = [p for p in msg.pieces if p.start >= piece.end]
    if any(_asks(p) and set(p.words) & POINTERS for p in after):
        return None  # "mine got shredded, can I have a new one": read as before
    return Finding("statement", piece, "what happened to the speaker's own thing: context only")


def _names_a_service(terms: Terms, piece: Piece) -> bool:
    """Whether the event names a service or facility of the office, or a waste container
    ("went in the compost", "got shredded", "went in the bin"): what a later rule would
    read as asked for."""
    if any(m.kind in ("cue", "facility") for m in piece.lexed.mentions):
        return True
    words = piece.words
    return any(
        tuple(words[k : k + len(p)]) == p
        for p in terms.en.waste_containers
        for k in range(len(words))
    )


def _asks(piece: Piece) -> bool:
    acts = piece.acts
    return piece.asks or acts.request or acts.imperative or acts.need


def _verb_at(words: list[str], items: Container[str]) -> int | None:
    """Where the verb after the speaker's own thing is ("mine *went*", "my old one *got*");
    a word that ends a name of the office's things is no verb ("my planning *set* needs
    ...", where "planning set" names the office's drawings)."""
    if not words:
        return None
    if words[0] in _OWN:
        return 1
    if words[0] not in _OWN_OPENERS:
        return None
    for k in range(2, min(len(words), _REACH + 1)):
        if any(" ".join(words[j : k + 1]) in items for j in range(1, k)):
            continue  # "my planning set": the thing's own name
        if _past(words, k):
            return k
        if words[k] in _MODALS or language.is_finite_verb(words[k]):
            return None  # "my affidavit *needs* the chartered stamp": a present verb first
    return None


def _past(words: list[str], k: int) -> bool:
    """A past verb at ``k`` ("went", "got", "was"), or a perfect ("has been shredded")."""
    if k >= len(words) or words[k] in _MODALS:
        return False
    if words[k] in _PERFECT:
        return k + 1 < len(words) and language.is_past_participle(words[k + 1])
    return language.is_past_verb(words[k]) and language.is_finite_verb(words[k])
