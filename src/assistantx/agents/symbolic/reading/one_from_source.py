"""ONE from a place: "Sue needs a highlighter, can you take one down from the cupboard".

A clause that names no thing of its own but says "one" (or "some") takes that word for the
thing the message has just asked for; the facility after "from" is where it comes from. A
clause with no thing and a facility that makes something was read as asking for the
facility's product ("grab me one from the cupboard": a notepad), which here added a second,
unasked-for delivery to the requester. Where a task came before in the same message, its thing
is what "one" stands for, and the clause only adds to that task (its source, its recipient).
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.core.task_schema import Task

# the words that stand for one more of a thing already named
_STAND_INS = frozenset({"one", "some"})


def one_of_the_previous(mentions: Sequence[Mention], previous: Task | None) -> bool:
    """Whether the clause's "one"/"some" stands for the thing of the task read before it."""
    if previous is None or previous.item is None:
        return False
    return any(m.kind == "word" and bool(m.ids) and m.ids[0] in _STAND_INS for m in mentions)
