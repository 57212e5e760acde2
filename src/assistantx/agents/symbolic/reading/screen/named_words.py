"""A word the lexicon reads as a colleague's name is no verb of the screen's lists.

"skip" and "bin" are verbs the screen acts on ("skip printing it" calls an errand off, "bin
my notes" disposes of them), and also names a colleague may have ("Skip Larsen", "Dang
Bin"). Where the lexicon has read the word as that person by its syntax ("Skip needs a
ruler", "Bin needs a stapler": a name before a finite verb), it is the subject of the
sentence, never the verb the screen looks for."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.english import split_words
from assistantx.agents.symbolic.reading.screen.pieces import Part, Piece


def token_at(piece: Piece, part: Part, at: int) -> int | None:
    """The index in ``piece``'s tokens of word ``at`` of ``part`` (the piece itself, or one
    of its sub-pieces), or None where the words and the tokens do not line up."""
    offset = part.start - piece.start
    if offset < 0 or at >= len(part.words):
        return None
    k = (len(split_words(piece.text[:offset])) if offset else 0) + at
    tokens = piece.lexed.tokens
    if k >= len(tokens) or tokens[k].word != part.words[at]:
        return None  # the words and the tokens do not line up: say nothing
    return k


def named_at(piece: Piece, part: Part, at: int) -> bool:
    """Whether word ``at`` of ``part`` (the piece itself, or one of its sub-pieces) is read
    in ``piece`` as a colleague's name."""
    k = token_at(piece, part, at)
    return k is not None and any(m.kind == "person" and m.start == k for m in piece.lexed.mentions)
