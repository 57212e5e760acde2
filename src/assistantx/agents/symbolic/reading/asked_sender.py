"""A colleague asked to send a file sends their own: "could Mark send me his file?", "can
Grace forward me her file", "would Hu email me the file?".

The subject of a request's modal ("could Mark ...") is the one asked to do what the verb says;
with a verb that sends a file, they send it, so the file is theirs (unless the words say whose:
"could Mark send Grace my file" is the speaker's, "... Ken's file" Ken's) and it goes to whom
the clause names, never back to them. "his"/"her" there is the sender's own, not the last
colleague named ("could Zhang send Wang his file?": Zhang's, to Wang)."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading._parties import Clause
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core.task_schema import FILE_KIND, Task

# the words before a file that leave whose it is to the sender ("his file", "the file")
_SENDERS_OWN = frozenset({"his", "her", "their", "the", "that", "this", "a"})


def sent_by_the_asked(
    made: Sequence[Task], asked: Sequence[str], clause: Clause, tokens: Sequence[Token]
) -> list[Task]:
    """``made`` with the file the one colleague ``asked`` (the subject of the request's
    modal) is to send read as theirs; unchanged where the tasks send no file, several or no
    colleague is asked, or the words say whose the file is."""
    if not made or any(t.kind != FILE_KIND for t in made) or len(set(asked)) != 1:
        return list(made)
    sender = asked[0]
    files = [m for m in clause.mentions if m.kind == "item"]
    if len(files) != 1:
        return list(made)
    before = tokens[files[0].start - 1] if files[0].start > 0 else None
    if before is not None and (before.possessive or before.word not in _SENDERS_OWN):
        return list(made)  # "Ken's file", "my file": whose it is, said
    return [t.model_copy(update={"owner": sender}) for t in made]
