"""A speaker who opens by naming themselves: "Bren here, my ruler is lost, can someone send
one over", "it's Ada, could someone bring me a ruler", "this is Ada Brennan - ...". The name
is one of the requester's own (full name, given name, alias, id): it introduces the speaker,
so it is left out before the message is read (on main "Bren here" made the speaker a party
to find, and whom the thing is for was asked). A colleague's name there ("Otto here?") is
never touched, nor an introduction that is the whole message.
"""

from __future__ import annotations

import re

from assistantx.core.office import Office
from assistantx.core.task_schema import Evidence

_GREETING = r"(?:(?:hi|hey|hello|morning|afternoon)\b[\s,!]*)?"
_AFTER = r"\s*(?:[,.:;!\u2013\u2014-]+\s*|\s+)"


def _spellings(office: Office, requester: str) -> list[str]:
    person = office.person(requester)
    words = person.name.split()
    found = {person.name, *person.aliases, person.id, person.id.replace("_", " ")}
    if words:
        found.add(words[0])
    return sorted((s for s in found if s.strip()), key=len, reverse=True)


def self_introduction(office: Office, requester: str, text: str) -> tuple[str, list[Evidence]]:
    """``text`` without an opening "<own name> here" / "it's <own name>" introduction."""
    try:
        names = _spellings(office, requester)
    except KeyError:
        return text, []
    if not names:
        return text, []
    name = "|".join(re.escape(n) for n in names)
    patterns = (
        rf"^\s*{_GREETING}(?P<name>{name})\s+here\b{_AFTER}",
        rf"^\s*{_GREETING}(?:it'?s|it\u2019s|this\s+is)\s+(?P<name>{name})\b\s*[,.:;!\u2013\u2014-]+\s*",
    )
    for pattern in patterns:
        match = re.match(pattern, text, re.IGNORECASE)
        if match is None or not text[match.end() :].strip():
            continue
        said = text[: match.end()].strip()
        return text[match.end() :], [Evidence(words=said, meaning="the speaker names themselves")]
    return text, []
