"""Whom a simulated operator sends a file their work made (a scan to PDF), read from the
code's message alone, as a colleague reads it: "... scan it, send the PDF to Wang Fang and put
it back" sends it to Wang Fang; "to yourself" to the operator; "to its owner", or a message
that names nobody there, to the paper's owner. A real colleague knows whom to send it to only
from these words, so the simulation must not know more (a planner that never says whom would
lose the delivery, and the evaluation must see that)."""

from __future__ import annotations

import re

from assistantx.core import language
from assistantx.core.office import Office

# "send the <file> to <whom>", up to the next clause ("and put it back") or the sentence's end
_SEND_TO = re.compile(r"\bsend the [^,.;!?]*? to (?P<to>[^,.;!?]+?)(?= and |[,.;!?]|$)", re.I)


def file_recipient(office: Office, told: str, owner: str, operator: str) -> str:
    """The person id the made file goes to (``owner`` unless the message names another)."""
    found = _SEND_TO.search(told)
    if found is None:
        return owner
    to = language.fold(found.group("to")).strip()
    if to == "yourself":
        return operator
    for person in office.people:  # by the name the code's message says (never an id)
        if language.fold(person.name) == to:
            return person.id
    return owner
