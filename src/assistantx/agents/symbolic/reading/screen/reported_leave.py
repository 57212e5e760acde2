"""The owner's yes, reported by the requester: "Zhang said I could have his stapler, just bring
it, no need to ask him", "Pat ok'd me using her seal, don't bother asking", "she gave me the
go-ahead". The requester wants the thing and says why they think asking is needless; they do
not ask that the owner be kept out. So a mark that skips asking, beside such a report, declines
nothing: the request is read as it stands and the owner is asked in their own chat as always
(text carries no authority: runtime/consent.py tells the requester that their claim grants
nothing and that the owner is still asked). Keeping the owner in the dark ("without telling
him", "while she's not looking") is declined whatever is reported; "he won't mind" is an
assumption, no reported yes (``reported_leave_marks``)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import starts_with
from assistantx.agents.symbolic.reading.screen.pieces import Message
from assistantx.core import english

_REPORTED = tuple(tuple(entry.split()) for entry in english.entries("reported_leave_marks"))


def reported_leave(msg: Message) -> bool:
    """Whether a piece of the message reports someone's yes (``reported_leave_marks``)."""
    return any(
        starts_with(p.words, n, mark)
        for p in msg.pieces
        for n in range(len(p.words))
        for mark in _REPORTED
    )
