"""The noun of a paper's parts left out of the text: "My CRF pages need the stamp on them" is
read as "My CRF need the stamp on them". The lexicon reads a paper's name with such a noun as
the paper (``paper_parts``); the screen that tells a request from a statement reads words, and
a part noun the office never names ("pages") left it a thing's unknown phrase ("my CRF
pages need ..." said as a fact, nothing done). Cut, the sentence is the one said of the paper
itself, which every stage reads.
"""

from __future__ import annotations

from assistantx.agents.symbolic.reading.aligned import aligned_reading
from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.paper_parts import PART_NOUNS


def without_paper_parts(lex: Lexicon, text: str) -> str:
    """``text`` with each part noun after a paper's name ("CRF *pages*") left out."""
    spans, tokens, mentions = aligned_reading(lex, text)
    if spans is None:
        return text
    cuts = [
        (spans[m.end - 2][1], spans[m.end - 1][1])
        for m in mentions
        if m.kind == "item"
        and m.end - m.start >= 2
        and tokens[m.end - 1].word in PART_NOUNS
        and lex.is_paper_part(tokens, m)
    ]
    for start, end in reversed(cuts):
        text = text[:start] + text[end:]
    return text
