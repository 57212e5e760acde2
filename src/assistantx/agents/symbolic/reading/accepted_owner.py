"""Whose one is fine: "i need a pen. Lee's is fine", "need a charger, Ruth's would do", "can
you bring me a stapler? Ana's works". After a need or a request, a colleague's possessive with
the thing left out and said to be acceptable picks that colleague's one (their consent is
asked, as for any owned thing). It is read as "Lee's please" in a sentence of its own, which
the frames read as the owner of the thing asked before. "Lee's is broken", "not Lee's" say no
such thing and are left alone; so is "it's fine", "that's fine" (no colleague), and a possessive
after a correction's word in its sentence ("... from Chen. actually, Lee's"): a correction,
read by the corrections.

The possessive offered as the choice says the same with nothing after it ("stapler pls,
Wang's") or with a condition on it ("a stapler, Wang's if he's not using it", "..., Ana's
as long as she doesn't mind"): whether the owner can spare it is what asking the owner finds
out, so the condition is read away with the choice. These two need the possessive set off by
punctuation from what comes before ("bring it to Wang's if he's in" names a place, not a
choice)."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import english
from assistantx.core.language import words as english_words

_ACCEPTABLE = sorted(english.entries("acceptable_said"), key=len, reverse=True)
_CONDITIONS = sorted(english.entries("choice_conditions"), key=len, reverse=True)


def _alternatives(phrases: list[str]) -> str:
    return "|".join(r"\s+".join(re.escape(w) for w in p.split()) for p in phrases)


_OWNER = r"(?P<owner>\b[^\W\d_]+)['’]s?"
_SAID_FINE = re.compile(
    r"(?P<before>\S)(?P<sep>\s*[,;:.!?]?\s*(?:[-–—]\s*)?)" + _OWNER + r"\s+"
    r"(?:" + _alternatives(_ACCEPTABLE) + r")\b",
    re.IGNORECASE,
)
# "stapler pls, Wang's" (the message or the sentence ends there), "..., Wang's if he's not
# using it" (the condition runs to the next pause or sentence end, and is read away)
_CHOSEN = re.compile(
    r"(?P<before>\S)(?P<sep>\s*(?:[,;:.!?]|\s[-–—])\s*)" + _OWNER + r"(?:"
    r"(?=\s*(?:[.!?;]|$))"
    r"|\s+(?:" + _alternatives(_CONDITIONS) + r")\b[^,.!?;]*"
    r")",
    re.IGNORECASE,
)


_REFUSALS = frozenset(english.words("exclusion_openers") | {"no"})
# the one-word marks of a correction ("actually", "sorry", "wait")
_MARKERS = frozenset(m for m in english.entries("owner_correction_markers") if " " not in m)
_SENTENCE_END = re.compile(r"[.!?;]")
_POSSESSIVE = re.compile(r"\b[^\W\d_]+['’]s\b")


def _chosen_here(text: str, at: int, is_person: Callable[[str], bool]) -> bool:
    """Whether the possessive offered at ``at`` follows a request with no owner of its own in
    its sentence: "not Lee's, Lin's" (a refusal before it) or "bring Lee's stapler, Lin's"
    (an owner already said) is a correction, read by the corrections."""
    said = _SENTENCE_END.split(text[:at])[-1]
    if set(english_words(said)) & (_REFUSALS | _MARKERS):
        return False  # "... from Chen. actually, Lee's": a correction, not a choice offered
    return not any(is_person(m.group(0)) for m in _POSSESSIVE.finditer(said))


def accepted_owners(text: str, is_person: Callable[[str], bool]) -> str:
    """``text`` with each "<colleague>'s is fine" (or "<colleague>'s" offered alone or with a
    condition) after something said read as "<colleague>'s please" in a sentence of its own
    (``is_person``: whether a word names a colleague)."""

    def said(match: re.Match[str]) -> str:
        owner = match.group("owner")
        owner = owner[:1].upper() + owner[1:]  # "lee's is fine": written as a name is
        if not is_person(f"{owner}'s"):
            return match.group(0)
        return f"{match.group('before')}. {owner}'s please"

    def chosen(match: re.Match[str]) -> str:
        if not _chosen_here(match.string, match.start("owner"), is_person):
            return match.group(0)
        return said(match)

    once = _SAID_FINE.sub(said, text)
    return _CHOSEN.sub(chosen, once)
