"""A reason sentence's description of a product ("Wang needs the budget printout for the
meeting. Can you print my file and take it to him?", "Zeynep needs the jacket pattern full
size for cutting. Can you plot my pattern file and take it to her?"): the words before the
product's name say what it shows, never a kind of it the office would have to make.

A product made from something (a printout of a file, a plot of a pattern file, a copy of a
paper) shows what that thing holds; a sentence that only states a colleague's need for it
(``Acts.need``: "X needs Y", no request of its own) is the reason for what the message then
asks, and where a later piece asks for the very work that makes that product ("print",
"plot"), the product is the one the request says ("my file", printed) and the need says whom
it is for. Read as a variant, the screen asked "a budget printout is not something this
office makes. Shall I get you an ordinary printout?" and, answered yes, did nothing.

Still a variant: a product made from nothing ("Basil needs an iced tea. Can you brew one for
him?": the words say which tea), a word that says how the thing is made rather than what it
shows (``product_finishes``: "a colour printout", "a laminated copy"; a size: "an A1 plot"),
the request's own words ("print my file in colour"), and a need with no request after it.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.core import english, language
from assistantx.core.office import Office

_HOW_MADE = english.words("product_finishes") | english.words("large_sizes")
_PAPER_SIZE = re.compile(r"^a[0-9]$")


def content_of_a_reason(
    office: Office, msg: Message, piece: Piece, product: str, words: Sequence[str]
) -> bool:
    """Whether ``words`` before ``product``'s name in ``piece`` describe what it shows:
    ``piece`` only states someone's need for a product made from something, and a later piece
    of ``msg`` asks for the work that makes it (by one of its operation's verbs)."""
    if not piece.acts.need or piece.acts.request:
        return False
    op = office.making(product)
    if op is None or op.input is None:
        return False
    if any(w in _HOW_MADE or _PAPER_SIZE.match(w) for w in words):
        return False
    verbs = {form for v in op.verbs for form in language.verb_forms(v)}
    later = [p for p in msg.pieces if p.start >= piece.end]
    return any(p.acts.request and verbs & {t.word for t in p.lexed.tokens} for p in later)
