"""Destructive: "throw away Wang's stapler", "hide ...", "get rid of ...": declined, unless
the office offers it as a service ("shred" where a shredder is)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import starts_with
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece, sub_pieces
from assistantx.agents.symbolic.reading.screen.terms import Terms


def destructive(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    for sub in sub_pieces(piece):
        at = sub.verb_at(terms.en.lead_in)
        for verb in terms.en.destructive:
            if verb[0] in terms.lex.operation_words:
                continue  # "shred my drafts" where a shredder is offered: a service
            if starts_with(sub.words, at, verb):
                said = " ".join(verb)
                return Finding(
                    "destructive",
                    piece,
                    f"destructive: {said}",
                    message=(
                        f"Sorry, I won't {said} anything: I don't dispose of, damage or take "
                        f"people's things. {terms.capabilities()}"
                    ),
                )
    return None
