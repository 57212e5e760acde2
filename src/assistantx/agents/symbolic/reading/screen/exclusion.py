"""Exclusion: "not from Wang though", "not Chen's": a hint that keeps that person's item
out, never a party to the errand."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core.task_schema import Hint


def exclusion(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """ "not from Wang though", "Not Chen's, they're blunt": that person's item is not
    wanted; a hint that keeps them out, never a party."""
    words = [w for w in piece.words if w not in ("but", "though", "just", "please")]
    if not words or words[0] not in terms.en.exclusion_openers:
        return None
    people = terms.named(piece.lexed, "person")
    items = terms.named(piece.lexed, "item") or terms.named(msg.lexed, "item")
    if len(people) != 1 or not items:
        return None
    who = terms.office.person(people[0]).name
    thing = terms.office.item_type(items[0]).name
    hint = Hint(
        kind="condition",
        person=people[0],
        value="not wanted",
        item_type=items[0],
        said=piece.text,
    )
    return Finding("exclusion", piece, f"not {who}'s {thing}", hint)
