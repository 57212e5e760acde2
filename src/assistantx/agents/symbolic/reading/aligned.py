"""A text's reading with the characters of each token: for the rewrites that cut or insert
words in the text itself ("Wang's setting-out file" → "Wang's file") from what the lexicon
read. Where the lexicon's tokens do not line up with the words of the text (a correction
joined or split words), there are no spans and the rewrite leaves the text alone."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Lexicon, Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import language


def aligned_reading(
    lex: Lexicon, text: str
) -> tuple[list[tuple[int, int]] | None, list[Token], list[Mention]]:
    """The character spans of ``text``'s tokens (None where they do not line up with the
    lexicon's tokens), the tokens and their mentions (none where they do not line up)."""
    lexed = lex.read(text)
    tokens = list(lexed.tokens)
    spans = [m.span() for m in language.WORD.finditer(text.replace("’", "'"))]
    if len(spans) != len(tokens):
        return None, tokens, []
    return spans, tokens, list(lexed.mentions)
