"""Chat shorthand of a function word written out before any stage: "mine hav gone walkabout
again", "wud u bring me a pen", "cn u grab the tape frm Olive".

The lexicon has always read each shorthand token as its word (english.yaml
``chat_shorthand``), but the screen, which splits a message into requests and statements,
reads the words as typed: "mine hav gone walkabout" was no statement about the speaker's own
pliers, and "mine" was read as the speaker's pliers asked for. The words are written out once,
as "r" is (``chat_copula``), so every stage reads the same sentence. A shorthand that is also a
word of the office's names (a colleague called "Cn") is left as typed."""

from __future__ import annotations

import re
from collections.abc import Collection

from assistantx.core import english

_SHORTHAND = english.wording("chat_shorthand")
_WORD = re.compile(
    r"(?<![\w'’&/.-])(" + "|".join(map(re.escape, sorted(_SHORTHAND))) + r")(?![\w'’&/-])",
    re.IGNORECASE,
)


def spelled_shorthand(text: str, office_words: Collection[str]) -> str:
    """``text`` with each chat shorthand word written out, a word of the office's own aside."""

    def spelled(m: re.Match[str]) -> str:
        typed = m.group(1)
        if typed.lower() in office_words:
            return typed
        word = _SHORTHAND[typed.lower()]
        return word[:1].upper() + word[1:] if typed[:1].isupper() else word

    return _WORD.sub(spelled, text)
