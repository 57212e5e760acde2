"""A count of things after a request, saying why it is made: "need envelopes pls, like 20
offer letters going out today", "paper please, got 30 invoices to print", "some tape, about
a dozen parcels to wrap". The part after the comma names how many of the speaker's things the
request serves; it asks nothing (no verb told to the robot, no question) and names no
colleague, so it is context: the things counted are no document to fetch or work on, and the
request before it is read as if it were not said.

What says so is English, not a list of papers: an opening of hedges or of having ("like",
"about", "got", "I've got"), then a number, then a plural noun. "..., and print my 20
letters" opens with a verb told to the robot and is a request of its own, read as before."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english, language

# Words that may open the count: a hedge on the number ("like 20", "about 30") or the
# speaker having the things ("got 30", "I've 20", "there are 40")
_OPENERS = frozenset(
    {"like", "about", "around", "roughly", "approx", "approximately", "maybe", "nearly"}
    | {"almost", "over", "some", "i", "we", "ive", "weve", "ve", "have", "got", "gotta"}
    | {"there", "theres", "are", "s", "cos", "because", "as", "since", "with", "a", "just"}
)
_NUMBERS = english.words("number_words") | frozenset({"dozen", "couple", "few", "hundred"})


def _count_at(words: list[str]) -> int | None:
    """Where the count's number is, when only opening words come before it."""
    for n, w in enumerate(words):
        if w.isdigit() or w in _NUMBERS:
            return n
        if w not in _OPENERS:
            return None
    return None


def counted_reason(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    del requester
    # no imperative test: the speech acts take "to print" after the count for a verb told
    # to the robot, but a piece that opens with a count opens with no verb at all
    if piece.asks or piece.acts.question is not None:
        return None
    if not msg.asked_before(piece):
        return None  # a count said alone is no reason for anything
    words = [t.word for t in piece.lexed.tokens]
    at = _count_at(words)
    if at is None:
        return None
    # "a dozen", "a couple of": the noun counted may come after "of"
    head = at + 2 if at + 1 < len(words) and words[at + 1] == "of" else at + 1
    if head >= len(words) or not language.is_plural_noun(words[head]):
        return None
    if terms.named(piece.lexed, "person") or any(t.possessive for t in piece.lexed.tokens):
        return None  # "20 of Rena's letters": a colleague's things, read as before
    return Finding("statement", piece, "how many things the request is for: context only")
