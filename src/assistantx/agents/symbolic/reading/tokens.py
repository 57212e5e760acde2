"""Stage 1 of the reader: text → tokens (words of any script, with their punctuation).

Nothing here knows an office: a token is the word as typed, its folded key (lower-case, no
diacritics, possessive removed: "Müller's" → ``muller``), whether it was possessive and whether
it opens a sentence. The lexicon (stage 2) corrects typos against the office's vocabulary and
finds the names; the tokens themselves never change after this stage.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass, replace

from assistantx.core import language
from assistantx.memory.names import TITLES

_SENTENCE_END = re.compile(r"[.!?;\n]")
# a comma, a colon, or a dash set off by spaces ("keys - key safe - now"): not "hi-vis"
_PAUSE = re.compile(r"[,:]|\s[-–—]+\s")


@dataclass(frozen=True)
class Token:
    text: str  # original spelling
    word: str  # folded (lower-case, no diacritics), possessive removed, typo-corrected
    possessive: bool
    typed: str = ""  # ``word`` before the typo correction
    opens: bool = False  # the first word of a sentence
    # a comma (or colon) before it: "needs a proofread, deal with it" is no compound noun
    after_pause: bool = False

    @property
    def corrected(self) -> bool:
        return bool(self.typed) and self.typed != self.word

    def corrected_to(self, word: str) -> Token:
        """The same token read as ``word`` (the lexicon's typo correction)."""
        return replace(self, word=word)


def tokenize(text: str) -> tuple[Token, ...]:
    """The words of ``text`` in order (Unicode: "José Müller's" is two words, the second
    possessive), each uncorrected (``word == typed``)."""
    flat = text.replace("’", "'")
    found = list(language.WORD.finditer(flat))
    out: list[Token] = []
    for n, match in enumerate(found):
        raw = match.group(0)
        if _bare_apostrophe(flat, match.start(), match.end()):
            raw += "'"  # "James' stapler", "miles' gauge": the apostrophe is the word's
        lower = language.fold(raw)
        possessive = lower.endswith("'s") or lower.endswith("s'")
        word = re.sub(r"'s$|'$", "", lower).replace("'", "")
        if not possessive and word.endswith("s'"):
            word = word[:-1]
        gap = flat[found[n - 1].end() : match.start()] if n else ""
        opens = n == 0 or bool(_SENTENCE_END.search(gap))
        out.append(Token(raw, word, possessive, word, opens, after_pause=bool(_PAUSE.search(gap))))
    return tuple(out)


def _bare_apostrophe(flat: str, start: int, end: int) -> bool:
    """Whether the word at ``start:end`` of ``flat`` ends in "s" with an apostrophe right
    after it and no letter after that ("James' stapler", "miles' gauge"): a plural or a
    name's possessive, not a closing quote ("the 'boss' stapler" opened one before it)."""
    if flat[end : end + 1] != "'" or not flat[start:end].lower().endswith("s"):
        return False
    if start > 0 and flat[start - 1] == "'":
        return False
    return end + 1 >= len(flat) or not flat[end + 1].isalnum()


def gaps(text: str, tokens: Sequence[Token]) -> tuple[str, ...]:
    """The characters between each token and the one before it (punctuation); a title's full
    stop ("Dr. Zhang") ends no sentence, so it is left out."""
    out: list[str] = []
    pos = 0
    prev_title = False
    flat = text.replace("’", "'")
    for t in tokens:
        at = flat.find(t.text, pos)
        gap = flat[pos:at] if at >= 0 else ""
        if out and prev_title:
            gap = gap.replace(".", "", 1)
        out.append(gap)
        pos = at + len(t.text) if at >= 0 else pos
        prev_title = t.word in TITLES
    return tuple(out)


def prev_word(tokens: Sequence[Token], start: int, *, skip_titles: bool = True) -> str:
    """The word before token ``start``; with ``skip_titles``, the one before "Dr."/"Ms"."""
    k = start - 1
    while k >= 0 and skip_titles and tokens[k].word in TITLES:
        k -= 1
    return tokens[k].word if k >= 0 else ""


def clause_start(tokens: Sequence[Token], at: int) -> int:
    """Where the clause of token ``at`` begins: at a token that opens a sentence or follows
    a pause, or at the first token."""
    while at > 0 and not (tokens[at].opens or tokens[at].after_pause):
        at -= 1
    return at


def clause_end(tokens: Sequence[Token], at: int) -> int:
    """Where the clause of token ``at`` ends: before the next token that opens a sentence or
    follows a pause, or at the end."""
    while at < len(tokens) and not (tokens[at].opens or tokens[at].after_pause):
        at += 1
    return at
