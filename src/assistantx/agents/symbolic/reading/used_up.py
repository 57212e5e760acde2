"""A request to use up someone else's item is declined as it is read (``core.owner_only``).

"shred Basil's ledger, he won't mind": the shredder's operation consumes the ledger, which is
Basil's, and only Basil can ask for that. The reader answers with the decline before anyone is
asked or anything moves; the runtime's consent guard refuses the same work code whatever
reasoner chose it. The requester's own item, nobody's item and work that gives the item back
are read as before.
"""

from __future__ import annotations

from assistantx.core.office import Office
from assistantx.core.owner_only import owner_only, owner_only_reason
from assistantx.core.task_schema import TaskFrame, operation_of


def declined_use_up(office: Office, frame: TaskFrame) -> TaskFrame:
    """The frame, or its decline when one of its tasks uses up an item of another person."""
    for task in frame.tasks:
        if task.item is None or task.owner is None:
            continue
        op = operation_of(office, task)
        owner = owner_only(office, frame.requester, f"{task.item}:{task.owner}", op)
        if owner is not None and op is not None:
            return TaskFrame(
                requester=frame.requester,
                decline=owner_only_reason(office, owner, task.item, op),
            )
    return frame
