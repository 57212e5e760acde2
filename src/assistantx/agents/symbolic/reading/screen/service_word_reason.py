"""A reason fragment after a request that names a service's facility or word: "could you get
me Sam's spreadsheet? need the laundry numbers", "..., for the laminator", "..., it's for the
wash rota".

A fragment that opens with the speaker's need ("need ...") or with "for" / "it's for", and
has no request verb of its own, says why the thing before it is asked for. The office's
service words in it (the laundry, the laminator, a wash) name a topic: a laundry's numbers
are no washing asked. Read with the request, the service took the request's thing as its
input ("wash a spreadsheet") and the request was declined.

Only such a fragment, and only one naming no thing of the office and no colleague: "need
my costume washed" (a thing, and its service's participle) and "also need a badge" ask for
work of their own; "for Sam" names whom the thing is for; and where the thing asked for is
what the service works on ("take my costume, for the laundry") the service is where it goes.
A reason that points back at the thing ("need it for the laundry") is ``purpose.reason``'s.
"""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.core import english

_NEED = english.words("need_verbs")
# the speaker, said or left out, before the need ("I need", "just need", "really need")
_SPEAKER = frozenset({"i", "we", "just", "really", "only", "still", "id"})
# "it's for", "that's for", "it is for", "this is for": the thing asked for, its use
_ITS_FOR = (("for",), ("its", "for"), ("thats", "for"), ("it", "is", "for"), ("this", "is", "for"))
# a second thing asked besides the first ("also need ...", "... too")
_MORE = frozenset({"also", "too", "another", "more", "plus"})


def service_word_reason(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """The fragment after a request that says why, naming a service only as its topic."""
    acts = piece.acts
    if piece.asks or acts.imperative or acts.question is not None:
        return None
    if not msg.asked_before(piece):
        return None
    words = content(piece.words)
    if not _reason_opening(words) or set(piece.words) & _MORE:
        return None
    if terms.named(piece.lexed, "item") or terms.named(piece.lexed, "person"):
        return None  # "need my costume washed", "for Sam": a thing or a colleague of its own
    mentions = piece.lexed.mentions
    tokens = piece.lexed.tokens
    if any(m.kind == "cue" and tokens[m.start].word not in _NEED for m in mentions):
        return None  # "need to wash the costumes": a verb of its own
    operations = [
        op
        for m in mentions
        if m.kind == "facility" and len(m.ids) == 1
        for op in map(terms.office.operation, terms.office.facility(m.ids[0]).operations)
    ] + [op for op in terms.office.operations if set(op.verbs) & set(words)]
    if not operations:
        return None
    asked = {item for p in msg.asked_before(piece) for item in terms.named(p.lexed, "item")}
    if any(op.input in asked for op in operations):
        return None  # "take my costume, for the laundry": the thing the service works on
    return Finding("statement", piece, "why the request is made, a service its topic: context")


def _reason_opening(words: list[str]) -> bool:
    k = 0
    while k < len(words) and words[k] in _SPEAKER:
        k += 1
    if k < len(words) and words[k] in _NEED:
        return True
    return k == 0 and any(tuple(words[: len(opening)]) == opening for opening in _ITS_FOR)
