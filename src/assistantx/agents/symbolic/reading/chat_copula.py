"""Chat "r" for "are": "bring me Gao's scissors, mine r blunt", "they r in the drawer", "r u
free?". The letter stands for the verb only where it stands as a word between a subject and
what is said of it (a pronoun or a plural noun before it, a word that can follow "are" after
it), or opens a question before a subject pronoun ("r u", "r you"); elsewhere ("plan r",
"R&D", "r/w") it is left as typed. Read once, before any stage, as "u" is read as "you"."""

from __future__ import annotations

import re

from assistantx.core import english, language

# Subjects "are" follows: the plural and second-person pronouns and the possessive ones that
# stand for a thing ("mine r blunt").
_SUBJECTS = frozenset(
    {"we", "you", "u", "they", "these", "those", "mine", "yours", "ours", "theirs", "hers"}
)
# Subjects a question opens on after "r" ("r u free?", "r they in?").
_ASKED = frozenset({"u", "you", "we", "they", "these", "those"})
_DETERMINERS = english.words("determiners")
_R = re.compile(r"(?<![\w'’&/.-])([rR])(?![\w'’&/-])")
_WORD = re.compile(r"[\w'’]+")


def spelled_are(text: str) -> str:
    """``text`` with each "r" that stands for "are" written out."""
    out: list[str] = []
    last = 0
    for m in _R.finditer(text):
        before = _WORD.findall(text[: m.start()])
        after = _WORD.findall(text[m.end() :])
        if _stands_for_are(before, after, text[: m.start()]):
            out.append(text[last : m.start()])
            out.append("Are" if m.group(1) == "R" else "are")
            last = m.end()
    out.append(text[last:])
    return "".join(out)


def _stands_for_are(before: list[str], after: list[str], head: str) -> bool:
    """Whether "r", after the words ``before`` (the text ``head``), stands for "are"."""
    if not after:
        return False
    nxt = after[0].lower()
    gap = head[head.rfind(before[-1]) + len(before[-1]) :] if before else ""
    if not before or any(c in gap for c in ".,;:!?-"):
        return nxt in _ASKED  # "r u free to ...": a question opens on it
    prev = before[-1].lower()
    subject = prev in _SUBJECTS or (prev.isalpha() and language.is_plural_noun(prev))
    return subject and _complement(nxt)


def _complement(word: str) -> bool:
    """A word that may follow "are": what the subject is (an adjective, a participle, an
    adverb, "not"), or where it is (a preposition); never a determiner or a plain noun."""
    if word in _PLACES or word == "not":
        return True
    if word in _DETERMINERS or not word.isalpha():
        return False
    return bool(set(language.lemmas(word)) & {"ADJ", "ADV", "VERB"})


# Where a thing is: "they r in the drawer", "r on my desk".
_PLACES = frozenset({"in", "on", "at", "under", "out", "by", "with", "over", "behind", "inside"})
