"""A work asked for by naming its tool: "put the clerk's stamp on my invoice and courier it
to Acme" asks for the stamp's work as surely as "stamp my invoice and courier it" does, though
no word of the clause is the work's verb (the tool's name is an item, not a cue). A later
clause on "it" is then more work on the same paper, never a sign that the first clause was
context ("my lunch is in the fridge, heat it": a clause of no work, whose task is dropped).

Only a task whose kind needs a tool (task_kinds: the seal's ``seals``) and whose clause names
that tool counts; a thing merely named ("the stamp is on my desk") makes no such task."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading._parties import Clause
from assistantx.core import task_kinds
from assistantx.core.office import Office
from assistantx.core.task_schema import Task


def works_by_named_tool(office: Office, clause: Clause, made: Sequence[Task]) -> bool:
    """Whether a task ``clause`` made is the work of a tool the clause names."""
    named = {m.id for m in clause.mentions if m.kind == "item"}
    return any(
        (tool := task_kinds.tool_type(t.kind, office)) is not None and tool in named for t in made
    )
