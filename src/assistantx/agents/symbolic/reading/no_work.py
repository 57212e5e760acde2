"""Work said to be lacking: "I have nothing to print", "I've got nothing to copy today",
"there's nothing to scan". "nothing to <verb>" tells that there is no such work: it asks for
none, though the verb is an office service's. Read as a request, the speaker's own file was
printed because the service's verb was said beside "I".

Only with "nothing" as the object of having ("have/has/'ve/'s/got nothing to ...") or opening
the clause, and with no "with"/"on" after the verb: "I have nothing to write with" lacks a
tool, a need (``lacked_purpose`` reads it), and so does "nothing to print it on".
"""

from __future__ import annotations

from collections.abc import Sequence

# the having of which "nothing" is the object: "I have nothing", "there's nothing", "got ..."
_HAVING = frozenset({"have", "has", "ve", "s", "got", "had", "theres", "ive", "weve"})
# what makes the lack a tool's, not the work's: "to write *with*", "to print it *on*"
_TOOL = frozenset({"with", "on", "onto", "into"})
# how far the tool's word may stand after the verb: "to print *the labels* on"
_TOOL_REACH = 4


def no_work_told(w: Sequence[str]) -> bool:
    """Whether the content words ``w`` of a piece say there is nothing to do ("I have nothing
    to print")."""
    for n, x in enumerate(w):
        if x != "nothing" or w[n + 1 : n + 2] != ["to"] or n + 2 >= len(w):
            continue
        if n > 0 and w[n - 1] not in _HAVING:
            continue  # "bring me nothing to ...": no having told
        return not set(w[n + 3 : n + 3 + _TOOL_REACH]) & _TOOL
    return False
