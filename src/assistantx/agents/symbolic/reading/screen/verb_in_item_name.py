"""A verb of the screen's lists that begins one of the office's item names is the item.

"bin", "scrap", "cut" are verbs the screen declines ("bin my notes", "cut up Ana's
contract"), and also the first words of names an office may give its supplies ("bin bags",
"scrap paper", "cut flowers"). The lexicon reads a thing's name by its longest match over
the office's names and synonyms, so where the words from the verb on spell such a name
("bin bags to desk 5 please") the name is what was said, and the verb reading is no reading
at all: English puts the object after a verb, not the rest of the verb's own noun. Where the
verb is followed by anything else ("bin the old bags", "bin these rubbish bags") no name
starts at the verb and it stays a verb."""

from __future__ import annotations

from collections.abc import Collection

from assistantx.agents.symbolic.reading.screen.named_words import token_at
from assistantx.agents.symbolic.reading.screen.pieces import Part, Piece

# the readings of the office's own names of things, as the lexicon tags them
_THING_KINDS = frozenset({"item", "facility"})


def opens_item_name(
    piece: Piece, part: Part, at: int, verb_words: int, names: Collection[str]
) -> bool:
    """Whether word ``at`` of ``part`` (the piece itself, or one of its sub-pieces) begins,
    in ``piece``'s reading, the name of one of the office's things longer than the verb's
    ``verb_words`` words, spelled there word for word as one of ``names`` (the lexicon also
    reads a name with a word between, "bin the bags"; that is the verb and its object)."""
    k = token_at(piece, part, at)
    if k is None:
        return False
    tokens = piece.lexed.tokens
    return any(
        m.kind in _THING_KINDS
        and m.start == k
        and m.end - m.start > verb_words
        and " ".join(t.word for t in tokens[m.start : m.end]) in names
        for m in piece.lexed.mentions
    )
