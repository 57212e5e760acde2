"""A thing taken to a colleague to have work done on it, and wanted back: "can you take my
declaration to Ivy to get it legalised? need it back by 3", "take my report to Wang to get it
copied and bring it back". "to get it <past participle>" after "take X to P" says what P is
there for: the work, not keeping the thing; "need it back" / "bring it back" says who ends up
with it: the requester. Read as "take X to P", the thing was handed to P after the work (a
wrong physical action). The clause is said as "get X <participle> by P", which the reader
already reads as the work done for the requester, the thing handed back to them.

Only with the requester's wanting it back said in the message (``_BACK``): "take my report to
Wang to get it copied" with no word of its return, and "take my signed contract to Wang"
(Wang keeps it) are left as said; only a colleague's name after "to", and only a past
participle the dictionary knows after "get it" / "have it"."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import language

_WORD = r"[^\W\d_][\w-]*"
_TAKEN = re.compile(
    rf"\b(?:take|bring|carry|run|drop)\s+(?P<thing>(?:my|our)\s+(?:{_WORD}\s+){{0,3}}?)"
    rf"(?:over\s+)?to\s+(?P<who>{_WORD}(?:\s+{_WORD})?)\s+"
    rf"(?:to|so\s+(?:he|she|they)\s+can|and)\s+(?:get|have)\s+(?:it|them)\s+(?P<done>{_WORD})\b",
    re.IGNORECASE,
)
# the requester's wanting the thing back: "need it back", "bring it back", "back to me"
_BACK = re.compile(
    r"\b(?:need|needs|want|wants|get|bring|have|send|return)\s+(?:it|them)\s+back\b"
    r"|\bback\s+to\s+me\b",
    re.IGNORECASE,
)


def taken_for_service(text: str, is_person_word: Callable[[str], bool]) -> str:
    """``text`` with a thing taken to a colleague to have work done on it, where the
    requester wants it back, said as that work done by them ("take my report to Wang to get it
    signed? need it back" → "get my report signed by Wang? need it back")."""
    if not _BACK.search(text):
        return text

    def by_them(m: re.Match[str]) -> str:
        who, done = m.group("who"), m.group("done")
        if not all(is_person_word(w) for w in who.split()):
            return m.group(0)  # "to the office": no colleague who does the work
        if not language.is_past_participle(done.lower()):
            return m.group(0)
        return f"get {m.group('thing')}{done} by {who}"

    return _TAKEN.sub(by_them, text)
