"""A message that opens by saying who speaks: "Shiv here - ...", "hi, Kit here. ...". The
sign-on names the speaker, no party to the request: it is read away, so a "him" or "her" later
in the message is never taken to mean the one who signed on. Only a colleague's name set off
by a dash, comma, colon or stop signs on: "Tam here needs a pen" is a need of Tam's, left
alone."""

from __future__ import annotations

import re
from collections.abc import Callable

_SIGNED_ON = re.compile(
    r"^\s*(?:(?:hi|hey|hello|hiya)\b[\s,!]*)?"
    r"(?P<name>[^\W\d_]+(?:\s+[^\W\d_]+)?)\s+here\s*[-–—,:.!;]+\s*",
    re.IGNORECASE,
)


def signed_on(text: str, is_person: Callable[[str], bool]) -> str:
    """``text`` without a colleague's opening sign-on (``is_person``: whether the words name
    a colleague)."""
    match = _SIGNED_ON.match(text)
    if match is None or not is_person(match.group("name")):
        return text
    rest = text[match.end() :]
    return rest[:1].upper() + rest[1:] if rest else text
