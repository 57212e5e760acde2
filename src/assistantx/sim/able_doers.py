"""Who could do the work a requester wants, where their goal names nobody to do it.

A goal such as "the lunch is heated", "the form is stamped" or "they hold a coffee" says what
must be true, not who makes it true: any keeper of a facility whose operation does the work
(or makes the thing), or any owner of the tool a person's work needs (a seal), will do. When
the assistant offers one of them in place of a colleague who is out ("Jo Bell isn't
available. Shall I ask Sam Reid instead?"), the simulated requester takes them as the doer
they did not name, not as someone they never asked for. A work milestone that names its doer
(a signature by Zhang) has no such stand-in.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.core import task_kinds
from assistantx.core.office import Office, Operation


def able_doers(office: Office, milestone: str, args: Sequence[str]) -> set[str]:
    """The people who could make a work ``milestone`` on ``args`` true (its item first) when
    it names no doer; empty for any other milestone."""
    if milestone in ("holds", "received") and len(args) == 2:
        # a thing made for them (a coffee, a printout): whoever runs a machine that makes it
        return _keepers(office, [o for o in office.operations if o.product == _type(args[1])])
    spec = task_kinds.of_milestone(milestone)
    if spec is None or not args:
        return set()
    type_id = _type(args[0])
    if spec.by_person:
        tool = task_kinds.tool_type(spec.id, office)
        if len(args) > 1 or tool is None:
            return set()  # a named doer's own work
        return {p.id for p in office.people if any(o.type == tool for o in p.owns)}
    if spec.shape is None:
        return set()
    return _keepers(
        office, [o for o in office.with_shape(spec.shape) if type_id in (o.input, o.product)]
    )


def _type(item_id: str) -> str:
    return item_id.partition(":")[0]


def _keepers(office: Office, operations: Sequence[Operation]) -> set[str]:
    """The keepers of every facility that offers one of ``operations``."""
    return {g for op in operations for f in office.offering(op.id) for g in f.guards}
