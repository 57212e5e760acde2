"""A task verb inside a fixed phrase that means something else: "take *care of* it", "take a
look at the printer". The verb there asks for no hand-over ("could you take care of that?" is
"could you handle that?"), so it is read as an ordinary word and the request is read by what
it points at. The phrases are general English (``english.yaml``: ``verb_idioms``)."""

from __future__ import annotations

import re
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


# "could Mo put her signature on my form", "adding his signature to it": a person's signature
# put on a paper is that person signing it (the verb's form kept: "putting" → "signing").
_SIGNATURE_PUT = re.compile(
    r"\b(?P<verb>put|puts|putting|add|adds|added|adding|stick|sticks|sticking)\s+"
    r"(?:(?:her|his|their|your|my|our|a)\s+)?(?:own\s+)?signature\s+(?:on|onto|to)\b",
    re.IGNORECASE,
)
_SIGN_FORMS = {"putting": "signing", "adding": "signing", "sticking": "signing"}


def signature_put(text: str) -> str:
    """The text with a signature said as put on a paper read as signing it ("could Mo put her
    signature on my form" → "could Mo sign my form"); a signature asked for by name ("Mo's
    signature on my form") is read by the signature's own rule."""

    def sign(match: re.Match[str]) -> str:
        verb = match.group("verb").lower()
        if verb in _SIGN_FORMS:
            return _SIGN_FORMS[verb]
        return "signs" if verb.endswith("s") else "signed" if verb == "added" else "sign"

    return _SIGNATURE_PUT.sub(sign, text)
