"""Two people joined by "and" before a possessive own the thing together, or each their own:
"bring me Wang and Sun's files" is Wang's file and Sun's file.

English marks a coordinated possessor once, on the last name ("Wang and Sun's"). Read one name
at a time, "Wang" was a bare name or, right after a giving verb, the recipient ("bring Wang
... to me" sent Sun's file to Wang), and Wang's own was dropped: a wrong hand-over. A single
person named right before "and" and a possessive name (nothing else between) is an owner of
the thing that possessive owns, not a party of the clause; the frame makes the errand for
each owner's thing (``each_owner``).
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core.task_schema import Task


def joined_owners(tokens: Sequence[Token], ms: Sequence[Mention]) -> dict[int, str]:
    """The first owner of each "A and B's" pair, keyed by the start of A's mention, with B's
    id: ``{start of A: B}`` (A is read as B's co-owner, B's possessive owns the thing)."""
    found: dict[int, str] = {}
    for a, b in itertools.pairwise(ms):
        if a.kind != "person" or a.possessive or len(a.ids) != 1:
            continue
        if b.kind != "person" or not b.possessive or len(b.ids) != 1:
            continue
        if [t.word for t in tokens[a.end : b.start]] == ["and"] and a.ids != b.ids:
            found[a.start] = b.ids[0]
    return found


def each_owner(made: Sequence[Task], co_owners: Mapping[str, Sequence[str]]) -> list[Task]:
    """The tasks with one for each co-owner's thing: a task on B's thing where A was joined
    to B ("Wang and Sun's files") is done on A's thing too, A's first (as said)."""
    out: list[Task] = []
    for task in made:
        owners = co_owners.get(task.owner or "", ())
        if task.owner is None or not owners:
            out.append(task)
            continue
        out += [task.model_copy(update={"owner": o}) for o in [*owners, task.owner]]
    return [t for n, t in enumerate(out) if t not in out[:n]]
