"""Emoji and other pictographs in a chat message: tone, never content.

"I've got 60 envelopes to label and no marker 😩" asks for the marker as plainly as without
the face; a pictograph at the end of a clause stood where the reader's clause rules look for
its end, so a rule that held on the words alone failed on the same words with a face after
them. They are taken out before anything reads the text, with what joins them to a word (an
emoji's variation selector, the zero-width joiner of a composed one, a skin-tone modifier):
by the Unicode category of each character, so any emoji, present or future, is covered."""

from __future__ import annotations

import re
import unicodedata

# "So": other symbols (every emoji, dingbats, ©); "Sk" only for the skin-tone modifiers,
# which are emoji parts (other modifier symbols, "^" and "`", are left alone)
_SKIN_TONES = range(0x1F3FB, 0x1F400)
_JOINERS = frozenset({"\u200d", "\ufe0e", "\ufe0f", "\u20e3"})


def _pictographic(c: str) -> bool:
    return unicodedata.category(c) == "So" or ord(c) in _SKIN_TONES or c in _JOINERS


_SPACES = re.compile(r"[ \t]{2,}")


def without_pictographs(text: str) -> str:
    """``text`` with its pictographs taken out and the spaces they left closed up."""
    if text.isascii():
        return text
    kept = "".join(c for c in text if not _pictographic(c))
    if kept == text:
        return text
    return _SPACES.sub(" ", kept).strip()
