"""A fault told the way chat tells it, with its auxiliary dropped: "printer jammed again",
"the labeller died again btw", "kettle broke this morning". A thing (a facility, an item, or
a thing the office does not know) and then how it failed, with only words of when or asides
after it: a statement, answered in words; nothing moves, and no name in it is asked about.

"the scanner jammed my strip" (what it did to something) and anything after the failure that
is more than a time or an aside are left to the other rules, and so is a colleague said to
have failed ("Wang broke it"): only a thing fails here. A person said beside it to be on it
("..., Wang is on it") is told, so the assistant does not ask for it to be reported."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.facility_report import REPAIR
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

_FAILED = tuple(
    sorted(
        (
            tuple(p.split())
            for p in english.entries("facility_failed") + english.entries("bare_failed")
        ),
        key=lambda p: -len(p),
    )
)
_TAILS = english.words("state_tails") | english.words("remark_tails")
_DETERMINERS = english.words("determiners")
_AUXILIARIES = frozenset({"has", "have", "had", "is", "was", "s", "just", "got"})
_SUBJECT_WORDS = 4  # "the big colour printer": the most words a thing is named with here


def bare_fault(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    acts = piece.acts
    if piece.asks or acts.request or acts.imperative or acts.question is not None:
        return None
    tokens, mentions = piece.lexed.tokens, piece.lexed.mentions
    words = [t.word for t in tokens]
    at, failed = _failure(words)
    if failed is None:
        return None
    subject = [w for w in words[:at] if w not in _DETERMINERS]
    if not subject or len(subject) > _SUBJECT_WORDS:
        return None
    if any(m.kind in ("person", "pronoun", "self") and m.start < at for m in mentions):
        # "Wang broke it": a colleague's doing, not a thing's fault; "my pen died": the
        # speaker's own thing, a lack the statements read (a spare may be asked next)
        return None
    if _AUXILIARIES.intersection(subject):
        return None  # "my charger has died": told with its auxiliary, read elsewhere
    if not all(w in _TAILS for w in words[at + len(failed) :]):
        return None  # "the scanner jammed my strip": what it did, read elsewhere
    said = " ".join([*subject, *failed])
    # someone named beside it is taken to be dealing with it ("..., Wang is on it")
    dealt = any(m.kind == "person" for p in msg.pieces if p is not piece for m in p.lexed.mentions)
    message = f"Thanks for letting me know the {said}."
    return Finding(
        "statement",
        piece,
        f"a report: the {said}",
        context=tuple(terms.named(piece.lexed, "item")),  # "..., can you get me another"
        message=message if dealt else f"{message} {REPAIR}",
    )


def _failure(words: list[str]) -> tuple[int, tuple[str, ...] | None]:
    """Where the first failure phrase starts after the thing's name, and the phrase."""
    for at in range(1, len(words)):
        for failed in _FAILED:
            if tuple(words[at : at + len(failed)]) == failed:
                return at, failed
    return 0, None
