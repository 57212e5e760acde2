"""The work the clause before asked for, by the verb it was said with ("*scan* my report and
send the pdf to Wang"): where an office runs two operations of one kind on the same paper (a
photocopy and a scan to PDF), the verb said picks one, and the later clause's "the pdf" is
that one's product.

Before this, the earlier task reached the reading of the later clause with no operation yet
(the verb is matched to an operation later, in ``operations``), so "the pdf" was weighed
against every operation of the kind; a photocopy makes paper, so "the pdf" was read as the
requester's own file: the scan went to the requester and their file to Wang. The verb's own
operation is used only where it is the one operation of that kind on that item the verb
names; otherwise the task is left as it was."""

from __future__ import annotations

from collections.abc import Set

from assistantx.core.office import Office
from assistantx.core.task_schema import SHAPE_KIND, Task


def as_said(previous: Task | None, ops_said: Set[str], office: Office) -> Task | None:
    """``previous`` with the operation its clause's verb named ("scan"), where that is the
    one operation of its kind on its item the verb names; else ``previous`` unchanged."""
    if previous is None or previous.operation is not None or previous.item is None:
        return previous
    named = [
        o
        for o in office.operations
        if o.id in ops_said
        and o.input == previous.item
        and SHAPE_KIND.get(o.shape(office)) == previous.kind
    ]
    if len(named) != 1:
        return previous
    return previous.model_copy(update={"operation": named[0].id})
