"""A paper's name followed by a noun of its parts is that paper: "my CRF *pages*", "the consent
form *sheets*", "Rose's contract *copies*" name the paper itself, its pages being how it is
handled. In English "pages", "sheets", "copies" after a paper's name are the compound's head
grammatically, but what they are pages of is the paper: stamping, signing or fetching them is
that work on the paper. Without this the part noun was read as nothing ("CRF pages need the
stamp": no item, "I'm not sure what you need") or as another thing of the office (its blank
"sheets" of paper, its photocopies).

Only a paper's or a file's name counts before the part noun (the office's signable or paper
things, its electronic file), and only right after it in the same phrase: "my contract, sheets
of paper too" (a pause) and "sheets for my contract" keep their reading.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english

# the nouns of a paper's parts or copies ("pages", "sheets"): English, not the office's
PART_NOUNS = english.words("paper_parts")


def part_of_paper(
    tokens: Sequence[Token], start: int, end: int, type_id: str, papers: Collection[str]
) -> int | None:
    """Where the item ``type_id`` said from ``start`` to ``end`` is a paper followed by a
    noun of its parts ("CRF *pages*"), the end of that noun; else None."""
    if type_id not in papers or end >= len(tokens) or tokens[end - 1].possessive:
        return None
    part = tokens[end]
    if part.opens or part.after_pause or part.word not in PART_NOUNS:
        return None
    return end + 1
