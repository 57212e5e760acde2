"""The speaker's own taking of a colleague's thing, announced: "I'm borrowing Wang's for the
afternoon, if he doesn't mind", "I'll be borrowing Hu's pen for a bit", "I'm going to nick
Wang's stapler for a sec". A first-person present progressive ("I'm borrowing"), future
progressive ("I'll be borrowing") or "going to" ("I'm going to / gonna borrow") of a verb of
borrowing (``borrow`` and English's ``taking_slang``: nick, pinch, swipe ...) with a
colleague's possessive after it says what the speaker is about to have: the thing is wanted
now, and whether its owner minds is what asking the owner finds out. It is read as the request it
stands for, "can I borrow Wang's ...", which the reader asks the owner about and brings.

Only the speaker's "I", in the present or future, and only a colleague's possessive: "I
borrowed Wang's stapler yesterday" (the past), "Wang is borrowing my stapler" (someone
else's taking), "I'm borrowing a pen" (nobody's to ask), "I'm returning Wang's stapler" (a
giving back) are left as said; so is the plain "I'll borrow Chen's" said beside a lack ("I
don't have a pen, I'll borrow Chen's"): the speaker's own remedy, decided and left to them."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import english, language

# The verbs of borrowing, one word each ("half inch" is left to be read as said).
_BORROWING = sorted(
    {"borrow"} | {w for w in english.entries("taking_slang") if len(w.split()) == 1},
    key=len,
    reverse=True,
)


def _forms(progressive: bool) -> str:
    """The verbs' bare forms, or their -ing forms ("nicking", "swiping")."""
    words = (
        [f for w in _BORROWING for f in language.verb_forms(w) if f.endswith("ing")]
        if progressive
        else _BORROWING
    )
    return "|".join(re.escape(w) for w in sorted(words, key=len, reverse=True))


_I = r"\bI\s*(?:['’]?\s*m|\s+am)"  # "I'm", "Im", "I am"
_I_WILL = r"\bI\s*(?:['’]?\s*ll|\s+will)"  # "I'll", "Ill", "I will"
_JUST = r"(?:\s+just)?"
# the head that announces the taking, then the colleague's possessive
_ANNOUNCED = re.compile(
    r"(?P<lead>\s*)(?P<join>\b(?:so|and|but|then)\s+)?"
    r"(?P<head>"
    rf"(?:{_I}|{_I_WILL}\s+be){_JUST}\s+(?:{_forms(True)})"
    rf"|(?:{_I}\s+(?:going\s+to|gonna)|\bgonna){_JUST}\s+(?:{_forms(False)})"
    r")"
    r"(?=\s+(?P<owner>[^\W\d_]+)['’]s?\b)",
    re.IGNORECASE,
)


def announced_borrowings(text: str, is_person_word: Callable[[str], bool]) -> str:
    """``text`` with each announced borrowing of a colleague's thing said as the request it
    stands for ("..., so can I borrow Wang's for the afternoon"); set off by a comma from a
    clause before it, so the reason said first stays a reason ("my stapler's broken")."""

    def asked(m: re.Match[str]) -> str:
        if not is_person_word(m.group("owner")):
            return m.group(0)  # "I'm borrowing the stapler": no colleague to ask
        before = text[: m.start()]
        sep = ", " if before and before[-1] not in ",;:.!?" else m.group("lead")
        return f"{sep}{m.group('join') or ''}can I borrow"

    return _ANNOUNCED.sub(asked, text)
