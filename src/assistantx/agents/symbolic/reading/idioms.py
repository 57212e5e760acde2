"""A task verb inside a fixed phrase that means something else: "take *care of* it", "take a
look at the printer". The verb there asks for no hand-over ("could you take care of that?" is
"could you handle that?"), so it is read as an ordinary word and the request is read by what
it points at. The phrases are general English (``english.yaml``: ``verb_idioms``)."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

_IDIOMS = tuple(
    sorted(
        {tuple(language.words(p)) for p in english.entries("verb_idioms")}, key=len, reverse=True
    )
)


def idiom_at(tokens: Sequence[Token], i: int) -> bool:
    """Whether the word at ``i`` opens one of the fixed phrases, within one sentence."""
    for phrase in _IDIOMS:
        span = tokens[i : i + len(phrase)]
        if len(span) == len(phrase) and all(
            t.word == w and (k == 0 or not t.opens)
            for k, (t, w) in enumerate(zip(span, phrase, strict=True))
        ):
            return True
    return False
