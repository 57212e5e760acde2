"""Stops that end no sentence: the full stop of an abbreviation ("Dr. Osei", "St. Mary's",
"e.g. the blue one", "approx. ten") is part of the word, not the end of a sentence.

Every later stage reads a ".", "!" or "?" between words as a sentence's end (the screen's
pieces, the tokens' sentence openings, the frames' clauses), so "get this signed by Dr. Osei
and then stamped" would be two sentences, the second ("Osei and then stamped") a statement
set aside, and only the signature done. The text is read once with those stops taken out,
before any stage; nothing else in it changes.

An initial's stop is taken out before a possessive ("Luca F.'s file": Luca F's, one name).
A title's stop is taken out only before a capitalised word (a name: "Dr. Osei"; "...see the
dr. Then print it" keeps its sentence end); a Latin or measure abbreviation's before any word.

The slashed shorthands of "with" and "without" ("leave it w/ Dr Vos", "a coffee w/o sugar")
are written out the same way: the slash is no word, so "w" alone named nobody to leave it with
and the printout came back to the speaker.
"""

from __future__ import annotations

import re

# Titles written with a stop before a name.
_TITLES = ("dr", "mr", "mrs", "ms", "mx", "prof", "st", "mt", "rev", "fr", "sr", "jr")
# Abbreviations of words, written with a stop before whatever follows.
_WORDS = ("e.g", "i.e", "eg", "ie", "approx", "incl", "esp", "vs", "cf", "ca")

_TITLE_STOP = re.compile(
    r"(?<![\w.])(" + "|".join(_TITLES) + r")\.(?=[ \t]+(?-i:[A-Z\u00C0-\u00DE]))", re.IGNORECASE
)
_WORD_STOP = re.compile(
    r"(?<![\w.])(" + "|".join(re.escape(w) for w in _WORDS) + r")\.(?=[ \t]*,?[ \t]*\w)",
    re.IGNORECASE,
)
# An initial's stop before a possessive ("Luca F.'s costings"): the name goes on.
_INITIAL_STOP = re.compile(r"(?<![\w.'’])([A-Za-z])\.(?=['’]s\b)")
# "w/ Dr Vos", "w/o sugar": a slashed shorthand before a space ("w/c" is another abbreviation).
_SLASHED = re.compile(r"(?<![\w/])([wW])/([oO])?(?=[ \t])")
# The inner stop of "e.g" and "i.e": the word is read as "eg", "ie".
_INNER = re.compile(r"(?<![\w.])([ei])\.([gie])(?=\b)", re.IGNORECASE)


def undotted(text: str) -> str:
    """``text`` with the stops of abbreviations before further words taken out and the
    slashed shorthands of "with" and "without" written out."""
    out = _TITLE_STOP.sub(r"\1", text)
    out = _WORD_STOP.sub(r"\1", out)
    out = _INITIAL_STOP.sub(r"\1", out)
    out = _INNER.sub(r"\1\2", out)
    return _SLASHED.sub(lambda m: "without" if m.group(2) else "with", out)
