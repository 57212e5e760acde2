"""A form said after a paper or a file picks which of the two is meant: "I need Wang's file,
the paper one" asks for Wang's paper document, "Wang's document, the pdf one" for Wang's
electronic file ("the hard copy", "the printed one", "the digital copy", "the electronic
one" alike), also as a sentence of its own ("can you get me Jie's report? the pdf one"). The
office keeps both forms of a colleague's paper as two things of its own (its
signable paper and its electronic file), so the form decides the errand: a hand-over or a
file sent. Before, "the paper one" named the office's blank paper (fetched as a second thing)
and "the pdf one" a second file with nobody to pass it to.

The pick is read from the office's own data: the head said before it must be a name of the
office's paper or file type (or an everyday noun of either, ``paper_nouns``/``file_nouns``,
that names no other thing of the office), and it is said again as the name of the picked
type, the pick dropped. A head that is no paper or file ("a cup, the paper one", "some paper,
the printed one" where paper is blank paper) and an office without both forms keep their words.
"""

from __future__ import annotations

import re

from assistantx.core import english, language
from assistantx.core.office import Office

_ELECTRONIC = english.words("electronic_formats") | english.words("electronic_picks")
_PAPER = english.words("paper_picks")
# the pause before the pick: a comma, a dash, a colon, or the end of a sentence ("Jie's
# report? the pdf one": the next sentence only picks); "the" or "a" opens it
_PAUSE = r"(?P<pause>\s*(?:[,;:.?!]+|\s[-–—]))\s*(?:i\s+mean\s+)?(?:the|a|an)\s+"
# a pick said as a sentence of its own ends there, polite words aside ("the pdf one pls");
# "print my report. the pdf one is on the drive" tells where the file is, no pick
_SENTENCE_ENDS = re.compile(r"\s*(?:[\w']+\s*)?(?:[.!?]|$)")
# a polite word may come between the head and the pause ("Wang's contract please, the pdf one")
_POLITE = english.words("polite")


def _alternation(phrases: set[str]) -> str:
    ordered = sorted(phrases, key=lambda p: (-len(p.split()), p))
    return "|".join(r"\s+".join(re.escape(w) for w in p.split()) for p in ordered)


class PickedForm:
    """The office's paper and file types, by their names, and the pattern of a pick."""

    def __init__(self, office: Office) -> None:
        paper = office.signable_type()
        file = office.file_type()
        self._names: dict[str, str] = {}
        self._pattern: re.Pattern[str] | None = None
        if paper is None or file is None:
            return  # nothing to pick between
        self._names = {"paper": office.item_type(paper).name, "file": office.item_type(file).name}
        heads = set(english.entries("paper_nouns")) | set(english.entries("file_nouns"))
        for t in (office.item_type(paper), office.item_type(file)):
            heads |= {language.fold(n) for n in (t.name, *t.synonyms)}
        # a name of another of the office's things is that thing ("some paper, the printed
        # one" where paper is the printer's blank paper): no paper or file to pick
        heads -= {
            language.fold(n)
            for t in office.item_types
            if t.id not in (paper, file)
            for n in (t.name, *t.synonyms)
        }
        forms = _ELECTRONIC | _PAPER
        polite = rf"(?P<polite>(?:\s+(?:{_alternation(set(_POLITE))}))?)"
        self._pattern = re.compile(
            rf"\b(?P<head>{_alternation(heads)}){polite}{_PAUSE}(?P<form>{_alternation(set(forms))})"
            rf"\s+(?:{_alternation(set(english.entries('picked_nouns')))})\b",
            re.IGNORECASE,
        )

    def __call__(self, text: str) -> str:
        """``text`` with each paper or file said with a pick named as the picked type."""
        if self._pattern is None:
            return text

        def picked(match: re.Match[str]) -> str:
            if any(c in match.group("pause") for c in ".?!"):
                rest = _SENTENCE_ENDS.match(text, match.end())
                closing = rest.group(0).strip(" .!?") if rest else None
                if closing is None or (closing and closing.lower() not in _POLITE):
                    return match.group(0)
            form = match.group("form").lower()
            name = self._names["paper" if form in _PAPER else "file"]
            return name + match.group("polite")

        return self._pattern.sub(picked, text)
