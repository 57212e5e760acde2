"""The plan's parts check: every task of the reading is carried by the plan, or nothing moves.

The reader asks about a part it cannot read (``reading.parts``); this is the same promise
kept where the plan is built, for whatever frame reaches the planner (the reader's, a
hybrid's, an answer's re-reading): a task that compiles to no step at all would count as
done at once, and a send-out with nowhere to send to cannot be run. Either is a part of the
request left out, so the whole request stops before its first physical step, saying which
part, instead of doing the rest and reporting "Done".

A task whose every step is with one and the same person (their own page proof taken from
them and handed straight back, nothing done to it on the way) moves nothing: reported done,
it would say "you now have your page proof" where the request asked for something else that
was lost (a legal read dropped while a clarifying answer was read). It stops the same way.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

from assistantx.core.office import Office
from assistantx.core.task_schema import Task, operation_of


class _Role(Protocol):
    @property
    def fixed(self) -> str | None: ...

    @property
    def facility(self) -> str | None: ...


class _Compiled(Protocol):
    @property
    def task(self) -> Task: ...

    @property
    def phases(self) -> Sequence[object]: ...


class _WithRoles(Protocol):
    @property
    def roles(self) -> Sequence[_Role]: ...


def left_out(office: Office, compiled: Sequence[_Compiled]) -> str | None:
    """Why a part of the reading is not in the plan (None: every task has its steps)."""
    for c in compiled:
        if not c.phases:
            return "I found no step that does it, so I did nothing"
        op = operation_of(office, c.task)
        if op is not None and office.operation(op).sends_out and not c.task.destination:
            return "I don't know where to send it, so I did nothing"
    return None


def moves_nothing(compiled: Sequence[_WithRoles]) -> str | None:
    """Why a task of the plan does nothing (None: each moves or changes something): every
    step with one and the same person, no facility on the way, so the item would be taken
    from them and handed straight back."""
    for c in compiled:
        people = {r.fixed for r in c.roles}
        if len(c.roles) >= 2 and len(people) == 1 and not any(r.facility for r in c.roles):
            return (
                "it would only be taken from its holder and handed straight back, so I did nothing"
            )
    return None
