"""A message that opens by saying who speaks: "Shiv here - ...", "hi, Kit here. ...". The
sign-on names the speaker, no party to the request: it is read away, so a "him" or "her" later
in the message is never taken to mean the one who signed on. Only a colleague's name set off
by a dash, comma, colon or stop signs on: "Tam here needs a pen" is a need of Tam's, left
alone.

Chat also signs on with initials or the speaker's own name before a colon at the very start
("JL: send my layout to Bjorn", "Jean-Luc: ..."): read away the same way, where the capitals
are the initials of a colleague of the office (``initials``) or the name is the speaker's
own. Whoever's initials they are, the sign-on never changes who asks (text carries no
authority): "JL: send my layout ..." from Dara sends Dara's layout. "FYI: ...", "NB: ..." are
no one's initials and are read as before."""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable

_SIGNED_ON = re.compile(
    r"^\s*(?:(?:hi|hey|hello|hiya)\b[\s,!]*)?"
    r"(?P<name>[^\W\d_]+(?:\s+[^\W\d_]+)?)\s+here\s*[-–—,:.!;]+\s*",
    re.IGNORECASE,
)


# "JL: ...", "J.L.: ...", "Jean-Luc: ...": initials in capitals, or a name, then a colon
_PREFIXED = re.compile(r"^\s*(?P<name>(?:[A-Z]\.?){2,4}|[^\W\d_]+(?:[-\s][^\W\d_]+)?)\s*:\s+(?=\S)")


def initials(names: Iterable[str]) -> frozenset[str]:
    """The initials colleagues of these names may sign with: all their name's words' ("JLR"
    for Jean-Luc Ricard), their given name's ("JL"), and the first and last ("JR")."""
    found: set[str] = set()
    for name in names:
        words = [w for w in re.split(r"[\s\-.]+", name) if w]
        letters = [w[0].upper() for w in words]
        if len(letters) < 2:
            continue
        found.update({"".join(letters), letters[0] + letters[-1]})
        if len(letters) > 2:
            found.add("".join(letters[:-1]))
    return frozenset(found)


def signed_on(
    text: str,
    is_person: Callable[[str], bool],
    *,
    signs: frozenset[str] = frozenset(),
    is_speaker: Callable[[str], bool] = lambda _: False,
) -> str:
    """``text`` without a colleague's opening sign-on (``is_person``: whether the words name
    a colleague; ``signs``: the initials of the office's colleagues; ``is_speaker``: whether
    the words name the one who speaks)."""
    match = _SIGNED_ON.match(text)
    if match is None or not is_person(match.group("name")):
        match = _PREFIXED.match(text)
        if match is None:
            return text
        name = match.group("name")
        if name.replace(".", "") not in signs and not is_speaker(name):
            return text
    rest = text[match.end() :]
    return rest[:1].upper() + rest[1:] if rest else text
