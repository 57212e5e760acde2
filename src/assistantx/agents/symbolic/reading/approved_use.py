"""A yes to the speaker's use of a thing, reported with a gerund: "Luca already ok'd me using
his stamp, just bring it", "Pat okayed my borrowing her tape", "Sam approved me having his
charger". The gerund is what the speaker was let do, so the clause says what "Pat said I could
use her stamp" says: the thing itself is wanted, and "bring it" hands it over (a transfer, with
Pat asked as always), never Pat's own stamping. The clause is said that way, so the reader
reads it as the reported leave it already knows.

Only after a verb of giving leave (``leave_verbs``) with the speaker ("me", "my", "us", "our")
and a verb in -ing that the dictionary knows: "Pat ok'd the budget" and "Pat approved my
leave" are left as said.

The leave reported with another verb of having the thing ("frank said I could borrow his
torch", "Wang says I can take her stapler", "she told me I could have it") is the same leave:
said as "use", it reads as the thing wanted (it had been a statement, "Noted."), and the owner
is asked as always."""

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


# "said I could borrow", "says I can take", "told me I could have": leave to have the thing
_HAVING = re.compile(
    r"\b(?:said|says|told\s+me)\s+(?:that\s+)?(?P<who>i|we)\s+(?:could|can|may|might)\s+"
    r"(?:borrow|have|take|grab|nab|pinch)\b",
    re.IGNORECASE,
)


def approved_uses(text: str) -> str:
    """``text`` with each reported leave for the speaker's doing said as "said I could <verb>"
    ("ok'd me using his stamp" → "said I could use his stamp"), and each reported leave to
    have a thing said with "use" ("said I could borrow his torch" → "said I could use his
    torch")."""
    text = _HAVING.sub(
        lambda m: f"said {'we' if m.group('who').lower() == 'we' else 'I'} could use", text
    )

    def said(m: re.Match[str]) -> str:
        verbs = sorted(language.verb_lemmas(m.group("doing").lower()))
        if len(verbs) != 1:
            return m.group(0)  # no verb the dictionary knows, or more than one: as said
        who = "we" if m.group("who").lower() in _WE else "I"
        return f"said {who} could {verbs[0]}"

    return _APPROVED.sub(said, text)
