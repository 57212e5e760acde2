"""Whose one is fine: "i need a pen. Lee's is fine", "need a charger, Ruth's would do", "can
you bring me a stapler? Ana's works". After a need or a request, a colleague's possessive with
the thing left out and said to be acceptable picks that colleague's one (their consent is
asked, as for any owned thing). It is read as "Lee's please" in a sentence of its own, which
the frames read as the owner of the thing asked before. "Lee's is broken", "not Lee's" say no
such thing and are left alone; so is "it's fine", "that's fine" (no colleague)."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import english

_ACCEPTABLE = sorted(english.entries("acceptable_said"), key=len, reverse=True)
_SAID_FINE = re.compile(
    r"(?P<before>\S)(?P<sep>\s*[,;:.!?]?\s*(?:[-–—]\s*)?)(?P<owner>\b[^\W\d_]+)['’]s?\s+"
    r"(?:" + "|".join(r"\s+".join(re.escape(w) for w in p.split()) for p in _ACCEPTABLE) + r")\b",
    re.IGNORECASE,
)


def accepted_owners(text: str, is_person: Callable[[str], bool]) -> str:
    """``text`` with each "<colleague>'s is fine" after something said read as "<colleague>'s
    please" in a sentence of its own (``is_person``: whether a word names a colleague)."""

    def said(match: re.Match[str]) -> str:
        owner = match.group("owner")
        owner = owner[:1].upper() + owner[1:]  # "lee's is fine": written as a name is
        if not is_person(f"{owner}'s"):
            return match.group(0)
        return f"{match.group('before')}. {owner}'s please"

    return _SAID_FINE.sub(said, text)
