"""Outside account: "send Joss's timesheet to my personal gmail", "email it to my home
address", "forward it to jo@example.org": a send to an account outside the office, which the
assistant has no channel to (it passes files to colleagues here). Declined in words, never
read as a send "to me" here; "send it to my email" (the requester's own, here) is read as
before."""

from __future__ import annotations

import itertools
import re

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english

# "personal email", "home address": an account of the speaker's own outside the office
_OUTSIDE = english.words("outside_account_marks")
_ACCOUNT = english.words("outside_account_nouns")
# a web mail service named by itself ("my gmail")
_WEB_MAIL = english.words("web_mail_services")
_ADDRESS = re.compile(r"[\w.+-]+@[\w-]+(?:\.[\w-]+)+")


def outside_account(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if not piece.acts.request:
        return None
    words = piece.words
    marked = any(
        a in _OUTSIDE and (b in _ACCOUNT or b in _WEB_MAIL) for a, b in itertools.pairwise(words)
    )
    if not (marked or set(words) & _WEB_MAIL or _ADDRESS.search(msg.text, piece.start)):
        return None
    return Finding(
        "unsupported",
        piece,
        "a send to an account outside the office",
        message=(
            "Sorry, I can't send anything to personal or outside email accounts: I can only "
            "pass things on to people here. I did nothing."
        ),
    )
