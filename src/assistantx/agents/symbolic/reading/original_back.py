"""The original of a copy, said after it: "make him a copy of it and bring me the original
back", "copy my report for Chen and give the original back to me".

A copy is made from a paper that someone puts in; the original comes back to them and the
copy goes to whom it is for (``task_kinds`` "copy"). A clause that only hands "the original"
back to the requester is that return, already part of the copy: it never makes the requester
the copy's recipient. "The original" handed to anyone else cannot be done by the copy as
planned, so it is asked, never guessed.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading._parties import Clause, Roles
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import task_kinds
from assistantx.core.task_schema import Task

_ORIGINAL = frozenset({"original", "originals"})

ORIGINAL_ELSEWHERE = (
    "The original of a copy comes back to whoever put it in, and the copy goes to whom it "
    "is for. Who should get the copy, and should the original come back to you?"
)


def original_back(task: Task, clause: Clause, tokens: Sequence[Token]) -> bool:
    """Whether ``clause`` (no task of its own) names "the original" after a task that makes
    a product of its item (a copy, a scan)."""
    if task_kinds.kind(task.kind).shape != "transform":
        return False
    said = {tokens[k].word for m in clause.mentions for k in range(m.start, m.end)}
    return bool(said & _ORIGINAL)


def original_of_copy(phrase: str, tasks: Sequence[Task]) -> bool:
    """Whether ``phrase`` ("the original") names the original of a copy some task makes:
    it is that copy's own return, never a thing the office has no name for."""
    words = set(phrase.lower().split())
    return bool(words & _ORIGINAL) and any(
        task_kinds.kind(t.kind).shape == "transform" for t in tasks
    )


def original_to_its_source(task: Task, roles: Roles, requester: str) -> bool:
    """Whether the clause hands the original to the one it comes back to anyway: the
    requester, who owns it or puts it in (or nobody named: "and keep the original")."""
    to = [*roles.recipient, *roles.returned_to]
    return all(who in (requester, task.owner) for who in to)
