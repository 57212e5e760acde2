"""Signs that join two requests as "and" does: "print my file + a coffee pls", "copy my
document & bring me a water". Chat writes "+" and "&" for "and"; set off by spaces they join
what is around them, so they are read as the word and every stage after reads the request as
if "and" were written. Left alone: a sign inside a word ("R&D", "Q&A", "C++"), a "+" before a
number ("+44 20 7946 0000": a phone number), and an "&" between two capitalised words, which
is a firm's or a place's name ("Harlow & Sons", "Hartwell & Co"). Chat's lower-case "n" set off by
spaces between two words ("scan my form n send the pdf to Grace") is "and" as well; a capital
"N" may be an initial, and "'n'" ("rock 'n' roll") is no lone letter."""

from __future__ import annotations

import re

# "+" with a space on each side, no number after it
_PLUS = re.compile(r"(?<=[^\s+&])\s+\+\s+(?=[^\s\d+&])")
# "&" with a space on at least one side, between two things said
_AMPERSAND = re.compile(r"(?<=[^\s+&])(?:\s+&\s*|\s*&\s+)(?=[^\s+&])")
# chat's "n" for "and": a lone lower-case letter between two words
_CHAT_N = re.compile(r"(?<=[^\W\d_])\s+n\s+(?=[^\W\d_])")
_WORD_BEFORE = re.compile(r"(\S+)$")
_WORD_AFTER = re.compile(r"^(\S+)")


def signs_as_and(text: str) -> str:
    """``text`` with every joining "+", "&" or chat's "n" written as "and"."""
    text = _PLUS.sub(" and ", text)
    text = _CHAT_N.sub(" and ", text)

    def joined(match: re.Match[str]) -> str:
        before = _WORD_BEFORE.search(text[: match.start()])
        after = _WORD_AFTER.search(text[match.end() :])
        if before and after and before.group(1)[:1].isupper() and after.group(1)[:1].isupper():
            return match.group(0)  # "Harlow & Sons": a name
        return " and "

    return _AMPERSAND.sub(joined, text)
