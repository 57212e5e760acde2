"""A thing fetched for the one spoken of, described by where it lies: "bring me the ruler at
Mark's desk", "get me the ruler that's next to Mark's desk", "fetch us the cup beside Dang's".

After a verb of fetching, "me" or "us" is the indirect object: the speaker receives, and a
place said right after the thing only tells which thing, where it lies. Read as it was, the
place was taken for where the thing goes and the ruler went to Mark (a wrong physical action);
"next to Mark's" with no noun was read as a second thing, Mark's own ruler, and two rulers
were fetched. A thing lying at a colleague's place is most likely theirs, and it is theirs to
lend in any case, so it is read as "bring me Mark's ruler": Mark is asked for it, as any owner
is, and a colleague with no such thing says no (nothing moves on a guess).

"next to Mark's lamp", "beside Will's calculator" say the same: where it lies, by a thing of
theirs, never a second thing asked for. A place that receives ("bring the ruler to Mark's
desk", "leave the ruler at Mark's desk": no "me" before the thing), a second thing joined by
"with", and more than one word after the possessive ("at Mark's desk drawer") are read as
before."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import english

_FOLLOWERS = english.words("place_possessive_followers")
_FETCHING = ("bring", "get", "fetch", "grab", "pass", "hand")
# "with Mark's calculator" joins a second thing, it says nowhere
_WHERE = ("at", "on", *(p for p in english.entries("nearness_phrases") if p != "with"))

_PLACED = re.compile(
    r"\b(?P<ask>(?:" + "|".join(_FETCHING) + r")\s+(?:me|us)\s+)"
    r"(?:the|that|this)\s+(?P<thing>[^\W\d_]+(?:\s+[^\W\d_]+)?)\s+"
    # "that's next to", "which is on", "lying on": a relative clause of where it is
    r"(?:(?:that|which)(?:['’]s|\s+is)\s+|(?:lying|sitting|left|kept)\s+)?"
    r"(?:" + "|".join(r"\s+".join(map(re.escape, p.split())) for p in _WHERE) + r")\s+"
    r"(?P<owner>[^\W\d_]+)['’]s\b"
    # what of theirs it lies by: their desk, or a thing ("next to Mark's lamp")
    r"(?:\s+(?P<landmark>[^\W\d_]+)\b)?"
    r"(?=\s*(?P<stop>[,;:.!?]|[-–—]|$)?\s*(?P<next>[^\W\d_]+)?)",
    re.IGNORECASE,
)


def placed_things(text: str, is_person: Callable[[str], bool]) -> str:
    """``text`` with each "<fetch> me the <thing> <where> <colleague>'s [desk]" read as
    "<fetch> me <colleague>'s <thing>" (``is_person``: whether a word names a colleague)."""

    def theirs(match: re.Match[str]) -> str:
        owner = match.group("owner")
        if not is_person(f"{owner}'s"):
            return match.group(0)
        landmark = (match.group("landmark") or "").lower()
        following = (match.group("next") or "").lower()
        if landmark in _FOLLOWERS:
            following = ""  # the bare possessive, then the sentence goes on
        if following and not match.group("stop") and following not in _FOLLOWERS:
            return match.group(0)  # "at Mark's desk drawer", "beside Will's blue lamp"
        # "next to Mark's and a pen": the word after the bare possessive is kept, read on
        kept = f" {match.group('landmark')}" if landmark in _FOLLOWERS else ""
        return f"{match.group('ask')}{owner}'s {match.group('thing')}{kept}"

    return _PLACED.sub(theirs, text)
