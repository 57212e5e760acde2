"""The plan's parts check: every task of the reading is carried by the plan, or nothing moves.

The reader asks about a part it cannot read (``reading.parts``); this is the same promise
kept where the plan is built, for whatever frame reaches the planner (the reader's, a
hybrid's, an answer's re-reading): a task that compiles to no step at all would count as
done at once, and a send-out with nowhere to send to cannot be run. Either is a part of the
request left out, so the whole request stops before its first physical step, saying which
part, instead of doing the rest and reporting "Done".
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

from assistantx.core.office import Office
from assistantx.core.task_schema import Task, operation_of


class _Compiled(Protocol):
    @property
    def task(self) -> Task: ...

    @property
    def phases(self) -> Sequence[object]: ...


def left_out(office: Office, compiled: Sequence[_Compiled]) -> str | None:
    """Why a part of the reading is not in the plan (None: every task has its steps)."""
    for c in compiled:
        if not c.phases:
            return "I found no step that does it, so I did nothing"
        op = operation_of(office, c.task)
        if op is not None and office.operation(op).sends_out and not c.task.destination:
            return "I don't know where to send it, so I did nothing"
    return None
