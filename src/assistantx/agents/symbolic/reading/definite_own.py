"""Whose item "the X" is when the requester sends it on to a colleague.

"take the stopwatch over to Kasia", said by someone who has a stopwatch of their own: the
definite article points at the one the speaker has at hand, their own, not one to be borrowed
from a colleague on the way; "take this permit to Dr Okafor" points at it all the more. Said
of an item the requester does not have ("take the radio to Femi"), with "a" ("bring Kasia a
stopwatch": any one will do), with a place or person it comes from ("the radio from Kasia"),
or to the requester themself ("bring me the stopwatch": they want one they do not have at
hand), the task is left as it was and the planner finds an owner.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading._parties import Clause, Roles
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core.office import Office
from assistantx.core.task_schema import Task

# "the", and the demonstratives of what is at hand ("this permit", "these forms")
_DEFINITE = frozenset({"the", "this", "these"})


def requesters_own(
    office: Office,
    tokens: Sequence[Token],
    clause: Clause,
    roles: Roles,
    task: Task,
    requester: str,
) -> Task:
    """``task`` with the requester as owner, when it takes "the X" (whose not said) to
    someone else and the requester owns an X; else ``task`` unchanged."""
    if task.kind != "transfer" or task.owner is not None or task.item is None:
        return task
    if task.recipient in (None, requester) or roles.source or roles.returned_to:
        return task
    if requester not in office.owners_of(task.item):
        return task
    said = [m for m in clause.objects() if m.id == task.item and m.start > 0]
    if len(said) != 1 or tokens[said[0].start - 1].word.lower() not in _DEFINITE:
        return task
    return task.model_copy(update={"owner": requester})
