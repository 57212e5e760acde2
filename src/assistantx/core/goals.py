"""Goal milestones (DESIGN §5): world-state predicates the simulator checks against the truth.

A milestone is a one-key mapping, as in the task files:
``{"holds": [person, item]}``, ``{"signed": [document, person]}``, ``{"sealed": document}``,
``{"printed": file}``, ``{"copied": document}``, ``{"heated": item}``,
``{"received": [person, file]}``, ``{"made": product}``, ``{"informed": person}``.
In ``holds``, an item ``type:*`` means any item of that type but the holder's own ("bring me
a stapler", also from someone whose own stapler is broken).
"""

from __future__ import annotations

from typing import Any

from assistantx.core import task_kinds

PREDICATES: dict[str, int] = {
    "holds": 2,
    "signed": 2,
    "sealed": 1,
    "printed": 1,
    "copied": 1,
    "heated": 1,
    "received": 2,
    "made": 1,
    "informed": 1,
}

Milestone = dict[str, Any]


def predicates() -> dict[str, int]:
    """Every predicate with its arity: the ones above, and the milestone of each
    person-to-person kind added to the table of kinds (``task_kinds.milestone_arity``)."""
    added = {
        k.milestone: arity
        for k in task_kinds.kinds()
        if k.milestone not in PREDICATES
        and (arity := task_kinds.milestone_arity(k.milestone)) is not None
    }
    return {**PREDICATES, **added}


def parse_milestone(raw: Any) -> tuple[str, tuple[str, ...]]:
    """Check a milestone's shape; return (predicate, arguments)."""
    if not isinstance(raw, dict) or len(raw) != 1:
        raise ValueError(f"a milestone is a mapping with one predicate, got {raw!r}")
    ((name, args),) = raw.items()
    known = predicates()
    if name not in known:
        raise ValueError(f"unknown predicate {name!r}; known: {', '.join(known)}")
    values = tuple(args) if isinstance(args, list | tuple) else (args,)
    if len(values) != known[name] or not all(isinstance(v, str) for v in values):
        raise ValueError(f"{name} takes {known[name]} string argument(s), got {args!r}")
    return name, values
