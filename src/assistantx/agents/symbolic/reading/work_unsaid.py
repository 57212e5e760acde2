"""Work on an item asked for with no verb that says which: "can you do something with my prep
before it turns", "deal with my prep please" where the office both vacuum-seals and
blast-chills prep.

With no task word in the request, the frames stage reads it as the item going somewhere, and
for the requester's own item that asks "Who should get your prep?": a question about a move
nobody asked for. Where the office runs several operations on that item, the request is far
more likely one of them, and which is the requester's to say: the question names them
("Which should I do with your prep: vacuum seal or blast chill?"), and the answer ("vacuum
seal") is read as that work done to it (``with_work``). A
request that says its work ("vac pack my prep", "bring me my prep") or an item only one
operation takes is read as before. Nothing is done before the answer.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.core.office import Office
from assistantx.core.task_schema import Task

WHICH_WORK = "Which should I do with your "
_POLITE_END = re.compile(r"[\s,]*(?:please|pls|thanks|thank you)?[\s.!?]*$", re.IGNORECASE)


def which_work(
    office: Office, tasks: Sequence[Task], mentions: Sequence[Mention], requester: str
) -> str | None:
    """The question which operation is meant, when no word of the request asks for any work
    and its one task would only bring the requester's own item back to them."""
    if any(m.kind == "cue" for m in mentions) or len(tasks) != 1:
        return None
    [task] = tasks
    if task.kind != "transfer" or task.item is None:
        return None
    if not (task.owner == task.recipient == requester) or task.source is not None:
        return None
    ops = [
        op
        for op in office.operations
        if op.input == task.item and office.runnable(op.id) and not op.sends_out
    ]
    if len(ops) < 2:
        return None
    names = [op.name for op in ops]
    name = office.item_type(task.item).name
    return f"{WHICH_WORK}{name}: {', '.join(names[:-1])} or {names[-1]}?"


def with_work(text: str, answer: str) -> str:
    """The request with the answer to ``WHICH_WORK`` said as the work done to its item:
    "... my prep before it turns. vacuum seal it"."""
    work = _POLITE_END.sub("", answer.strip())
    return f"{text.rstrip(' .!?')}. {work} it"
