"""A yes to the speaker's use of a thing, reported with a gerund: "Luca already ok'd me using
his stamp, just bring it", "Pat okayed my borrowing her tape", "Sam approved me having his
charger". The gerund is what the speaker was let do, so the clause says what "Pat said I could
use her stamp" says: the thing itself is wanted, and "bring it" hands it over (a transfer, with
Pat asked as always), never Pat's own stamping. The clause is said that way, so the reader
reads it as the reported leave it already knows.

Only after a verb of giving leave (``leave_verbs``) with the speaker ("me", "my", "us", "our")
and a verb in -ing that the dictionary knows: "Pat ok'd the budget" and "Pat approved my
leave" are left as said."""

from __future__ import annotations

import re

from assistantx.core import english, language

_LEAVE = "|".join(
    re.escape(v).replace(r"\ ", r"\s+")
    for v in sorted(english.entries("leave_verbs"), key=len, reverse=True)
)
_APPROVED = re.compile(
    rf"\b(?P<verb>{_LEAVE})\s+(?P<who>me|my|us|our)\s+(?P<doing>[^\W\d_]+ing)\b", re.IGNORECASE
)
_WE = frozenset({"us", "our"})


def approved_uses(text: str) -> str:
    """``text`` with each reported leave for the speaker's doing said as "said I could <verb>"
    ("ok'd me using his stamp" → "said I could use his stamp")."""

    def said(m: re.Match[str]) -> str:
        verbs = sorted(language.verb_lemmas(m.group("doing").lower()))
        if len(verbs) != 1:
            return m.group(0)  # no verb the dictionary knows, or more than one: as said
        who = "we" if m.group("who").lower() in _WE else "I"
        return f"said {who} could {verbs[0]}"

    return _APPROVED.sub(said, text)
