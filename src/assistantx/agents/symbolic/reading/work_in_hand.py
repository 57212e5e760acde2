"""The work in hand beside the speaker's lack is the lack's purpose: "I've run out of wipes
and have ten desks to clean", "I've got 40 forms to sign and no pen", "I have no stapler and
30 reports to bind". The things the work is done to ("ten desks", "40 forms") are why the
thing lacked is wanted, never a second request: the clause is said as the lack's purpose
("I've run out of wipes to clean ten desks", "I have no pen to sign 40 forms"), which the
reader already reads as the want of the thing for that work. A verb that is also a
colleague's name ("to mark up" where Mark works) is said as a gerund after "for" ("for
marking up"), never "to Mark". Only a clause of "have"/"got",
a quantity or article, its things and "to" and a verb: "I'm out of paper, can you print my
report?" asks on its own and is read as before."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import english


def _loose(word: str) -> str:
    """``word`` as the language data writes it ("ive"), said with or without its apostrophe
    ("I've", "ive")."""
    return "['’]?".join(re.escape(c) for c in word)


def _any_phrase(key: str) -> str:
    phrases = sorted(english.entries(key), key=len, reverse=True)
    return "|".join(r"\s+".join(_loose(w) for w in p.split()) for p in phrases)


# who has the work: "I've got", "have", "got" (the speaker's, said or left out)
_HAVE = r"(?:i\s*['’]?\s*ve\s+got|i\s+have\s+got|i\s*['’]?\s*ve|i\s+have|i\s+got|got|have)"
# the things worked on, counted or with their article: "ten desks", "40 forms", "a report",
# "a stack of letters"; at most four words before "to"
_COUNT = rf"(?:an?|the|some|\d+|{_any_phrase('number_words')}|loads\s+of|lots\s+of)"
_LOAD = rf"(?P<load>{_COUNT}\s+(?:[a-z'’-]+\s+){{0,3}}?[a-z'’-]+)"
_WORK = rf"{_LOAD}\s+to\s+(?P<verb>[a-z]+)(?P<rest>[^.!?;,]*)"
# "<lack>, and have ten desks to clean"
_LACK_THEN_WORK = re.compile(
    rf"(?P<lack>\b(?:{_any_phrase('speaker_lack_phrases')})\s+[^.!?;,]*?)\s*,?\s+"
    rf"(?:and|so|but|with)\s+(?:{_HAVE}\s+)?{_WORK}",
    re.IGNORECASE,
)
# "(I've got) 40 forms to sign and no pen" at the start of a sentence
_WORK_THEN_LACK = re.compile(
    rf"(?:^|(?<=[.!?;]))(?P<lead>\s*)(?:{_HAVE}\s+){_LOAD}\s+to\s+(?P<verb>[a-z]+)"
    r"(?P<rest>[^.!?;,]*?)\s*,?\s+(?:and|but)\s+(?:no|not\s+a|not\s+one)\s+"
    r"(?P<thing>[a-z][a-z '’-]*?)\s*(?=[.!?;,]|$)",
    re.IGNORECASE,
)


def work_as_purpose(
    text: str,
    lacks: Callable[[str], bool],
    names_item: Callable[[str], bool],
    is_person_word: Callable[[str], bool],
) -> str:
    """``text`` with the work in hand said as the purpose of the speaker's lack beside it;
    ``lacks``: whether a clause is the speaker's lack of one of the office's items,
    ``names_item``: whether a phrase names one, ``is_person_word``: whether a phrase
    names a colleague ("to mark")."""

    def to_do(verb: str) -> str:
        return f"for {gerund(verb)}" if is_person_word(f"to {verb}") else f"to {verb}"

    def purpose(match: re.Match[str]) -> str:
        if not lacks(match.group("lack")):
            return match.group(0)
        return (
            f"{match.group('lack')} {to_do(match.group('verb'))} {match.group('load')}"
            f"{match.group('rest')}"
        )

    def lacked(match: re.Match[str]) -> str:
        if not names_item(match.group("thing")):
            return match.group(0)
        return (
            f"{match.group('lead')}I have no {match.group('thing')} "
            f"{to_do(match.group('verb'))} "
            f"{match.group('load')}{match.group('rest')}"
        )

    return _WORK_THEN_LACK.sub(lacked, _LACK_THEN_WORK.sub(purpose, text))


_VOWELS = frozenset("aeiou")


def gerund(verb: str) -> str:
    """The -ing form of a regular verb: "staple" → "stapling", "wrap" → "wrapping", "sign" →
    "signing", "tie" → "tying"; a final consonant is doubled after one short vowel in a
    word of one syllable ("cut", "wrap"; not "edit", "mark", "clean")."""
    v = verb.lower()
    if v.endswith("ie"):
        return f"{v[:-2]}ying"
    if v.endswith("e") and not v.endswith(("ee", "ye", "oe")) and len(v) > 2:
        return f"{v[:-1]}ing"
    syllables = sum(
        1 for a, b in zip(" " + v, v, strict=False) if b in _VOWELS and a not in _VOWELS
    )
    if (
        syllables == 1
        and len(v) >= 3
        and v[-1] not in _VOWELS | {"w", "x", "y"}
        and v[-2] in _VOWELS
        and v[-3] not in _VOWELS
    ):
        return f"{v}{v[-1]}ing"
    return f"{v}ing"
