"""Emoji and other pictographs in a chat message: tone, never content.

"I've got 60 envelopes to label and no marker 😩" asks for the marker as plainly as without
the face; a pictograph at the end of a clause stood where the reader's clause rules look for
its end, so a rule that held on the words alone failed on the same words with a face after
them. They are taken out before anything reads the text, with what joins them to a word (an
emoji's variation selector, the zero-width joiner of a composed one, a skin-tone modifier):
by the Unicode category of each character, so any emoji, present or future, is covered.

A pictograph between two words stands where a writer would put a comma or a full stop
("Ivy's forgotten her lead again 🙄 can you take her mine"): the face closes the first
clause, so it is read as a comma, never as nothing (which ran "again can you ..." into one
clause). A face typed in ASCII (":(", ";)", "xD") standing alone is one too. Not after a
determiner ("a ☕ from the kitchen", "my 🔑"):
there the pictograph stands for a word of the clause, and the clause goes on."""

from __future__ import annotations

import re
import unicodedata

from assistantx.core import english

# "So": other symbols (every emoji, dingbats, ©); "Sk" only for the skin-tone modifiers,
# which are emoji parts (other modifier symbols, "^" and "`", are left alone)
_SKIN_TONES = range(0x1F3FB, 0x1F400)
_JOINERS = frozenset({"\u200d", "\ufe0e", "\ufe0f", "\u20e3"})


def _pictographic(c: str) -> bool:
    return unicodedata.category(c) == "So" or ord(c) in _SKIN_TONES or c in _JOINERS


# a face typed with ASCII, standing alone between spaces ("my epee's dead again :( can it
# ..."): a pictograph like any other
_TYPED_FACE = re.compile(r"(?<!\S)(?:[:;=]['’]?-?[()DPpOo/\\|\]\[3*]+|xD|XD|<3)(?!\S)")
_SPACES = re.compile(r"[ \t]{2,}")
# a run of pictographs (and spaces) with a word right before and a word right after
_BETWEEN_WORDS = re.compile(r"(?<=\w)(\s*)(\x00+)(\s*)(?=\w)")
_MARK = "\x00"
# words a noun must follow: a pictograph after one stands for that noun
_DETERMINERS = english.words("determiners")


def without_pictographs(text: str) -> str:
    """``text`` with its pictographs (and the faces typed in ASCII, ":(", ";)", "xD") taken
    out and the spaces they left closed up; one (or a run) between two words is a comma
    ending the clause before it, or a space after a determiner ("a ☕ from the kitchen")."""
    typed = _TYPED_FACE.sub(lambda m: _MARK * len(m.group(0)), text)
    if typed.isascii() and typed == text:
        return text
    marked = "".join(_MARK if _pictographic(c) else c for c in typed)
    if marked == text:
        return text
    kept = _BETWEEN_WORDS.sub(lambda m: _between(marked, m), marked).replace(_MARK, "")
    return _SPACES.sub(" ", kept).strip()


def _between(text: str, m: re.Match[str]) -> str:
    """What a pictograph between two words becomes: a comma ending the clause before it,
    except after a determiner, where it stood for a noun and the clause goes on."""
    before = re.findall(r"[\w']+", text[: m.start()])
    if not m.group(1) and not m.group(3):
        return ""  # inside a word ("co😀de"): no clause ends there
    if before and before[-1].lower() in _DETERMINERS:
        return " "
    return ", "
