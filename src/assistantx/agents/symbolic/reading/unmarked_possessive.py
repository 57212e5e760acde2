"""A colleague's possessive typed without its apostrophe: "Grants off today, hes at the
dentist", "can you get Amaras spreadsheet", "could I borrow Lucas Bs stopwatch", "sam ws
card reader". The lexicon already read a misspelt "wangs" as Wang's, but only word by word:
the screen, which splits a message into statements and requests, read "Grants off today" as
nothing it knew, and a name that is also an ordinary word ("Frank", "Grant") kept its plural.
Each such word is written with its apostrophe once, before any stage, so every stage reads
the same possessive.

A word is marked where it is a colleague's name word with an "s" after it, and is no name
word itself ("Lucas" stays Lucas): always where it is written with a capital ("Grants",
"Franks"), and in lower case only where the dictionary does not know it ("amaras", "okoros";
"grants" and "franks" in lower case stay words). A one-letter initial ("Bs", "ws") is marked
only after the given name it belongs to ("Lucas Bs", "sam ws")."""

from __future__ import annotations

import re
from collections.abc import Callable, Collection

from assistantx.core import language

_UNMARKED = re.compile(r"(?<![\w'’])(?P<stem>[^\W\d_]+)s(?![\w'’])")
_BEFORE = re.compile(r"([^\W\d_]+)\s+$")


def marked_possessives(
    text: str, name_words: Collection[str], is_person: Callable[[str], bool]
) -> str:
    """``text`` with each colleague's possessive written with its apostrophe."""

    def mark(match: re.Match[str]) -> str:
        stem = match.group("stem")
        word = match.group(0)
        if word.lower() in name_words or stem.lower() not in name_words:
            return word
        if not word[0].isupper() and language.lemmas(word.lower()):
            return word  # "grants", "franks": the ordinary words
        if len(stem) == 1:
            before = _BEFORE.search(match.string, 0, match.start())
            if before is None or not is_person(f"{before.group(1)} {stem}"):
                return word  # "As", "Os": a letter of no name said before it
        return f"{stem}'s"

    return _UNMARKED.sub(mark, text)
