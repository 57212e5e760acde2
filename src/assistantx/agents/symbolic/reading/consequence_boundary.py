"""A consequence's "so" said without its comma: "my stapler is broken so can I borrow Wang's",
"my stapler's broken so yeah could you bring me Wang's". Between a statement and a question
or request the "so" starts a clause of its own, as it does after a comma; the reader's clause
splitting looks for the comma, so the comma is put back before the "so". A filler said after
the "so" ("yeah", "anyway") says nothing and is dropped.

Only where what follows the "so" opens an ask: a request modal or question auxiliary with its
subject and more words after ("so can I borrow ...", "so could you bring ..."), a word of
asking ("so please bring ..."), a verb of giving with whom or what it gives ("so bring me some
staples", "so grab a new one"), or "that's why". So the degree adverb ("I'm so tired", "it's
so broken"), "do so", "so that I can sign" and the short "so do I" stay as said, and so does a
"so" that opens the text ("so can you bring me a pen": a request already)."""

from __future__ import annotations

import re

from assistantx.core import english


def _alternatives(*keys: str) -> str:
    words = {w for key in keys for w in english.entries(key) if " " not in w}
    return "|".join(re.escape(w) for w in sorted(words, key=len, reverse=True))


_ASKING_AUX = _alternatives("request_modals", "question_auxiliaries")
_ASKEES = _alternatives("request_askees", "owner_determiners")
_POLITE = _alternatives("polite")
_FILLERS = _alternatives("consequence_fillers")
_DATIVE = _alternatives("dative_verbs")
_GIVEN_TO = _alternatives("receiver_pronouns", "determiners")
# "do so", "did so": "so" is the done thing's object, no clause of its own
_DOING = frozenset({"do", "does", "did", "doing", "done"})

_UNMARKED_SO = re.compile(
    rf"(?<=[\w'’]),?\s+so(?:\s+(?:{_FILLERS})\b)*\s*,?\s+"
    r"(?=(?:"
    # "so can I borrow ...", "so could you ...", "so can my form get the seal on it"
    rf"(?:{_ASKING_AUX})\s+(?:{_ASKEES})\s+\w"
    rf"|(?:{_POLITE})\s+\w"  # "so please bring ..."
    rf"|(?:{_DATIVE})\s+(?:{_GIVEN_TO})\s+\w"  # "so bring me some staples", "so get a new one"
    r"|that['’]?s\s+why\b"  # "so that's why ..."
    r"))",
    re.IGNORECASE,
)


def consequence_boundaries(text: str) -> str:
    """``text`` with a comma before each "so" that joins a statement to the ask after it
    without one, and the fillers after that "so" dropped."""

    def bounded(m: re.Match[str]) -> str:
        before = re.findall(r"[\w'’]+", text[: m.start()])
        if before and before[-1].lower() in _DOING:
            return m.group(0)
        return ", so "

    return _UNMARKED_SO.sub(bounded, text)
