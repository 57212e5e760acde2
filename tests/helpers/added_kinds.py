"""A task kind a test adds to the live table: one of the signing shape (a colleague works on
the requester's signable paper: its source deposits it, the doer does the work, the recipient
collects it), and the table with it added for the length of a ``with``."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

from assistantx.core import task_kinds
from assistantx.core.task_kinds import KindSpec, Step


def signing_kind(
    kind_id: str,
    verb: str,
    past: str,
    doer: str,
    *,
    words: tuple[str, ...],
    milestone: str | None = None,
) -> KindSpec:
    """A kind like ``sign``: "get my form {past} by Wang" (``verb``: "approve", ``past``:
    "approved"); its part, purpose and the doer's step are named ``kind_id``, its milestone
    ``past`` unless given."""
    return KindSpec(
        id=kind_id,
        parts=(kind_id,),
        milestone=milestone or past,
        by_person=True,
        works_on="signable",
        ask=f"{verb} {{whose}}",
        purpose=kind_id,
        doer=doer,
        steps=(Step("source", "deposit"), Step("doer", kind_id), Step("recipient", "collect")),
        locker=f"take {{item}} out, {verb} it and put it back",
        todo=f"get {{whose}} {past} by {{by}}",
        done=f"{{whose}} was {past} by {{by}} and handed to {{to}}",
        words=words,
    )


@contextmanager
def kind_added(spec: KindSpec) -> Iterator[KindSpec]:
    """The live task-kind table with ``spec`` in it, taken out again after."""
    task_kinds.add(spec)
    try:
        yield spec
    finally:
        task_kinds.remove(spec.id)
