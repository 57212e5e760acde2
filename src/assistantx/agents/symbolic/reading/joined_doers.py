"""People joined by "and" where the doer of a person's work stands: each of them does it.

"get my contract signed by Wang and Zhang", "I need Wang and Zhang to sign my contract", "ask
Hal, Dawn and Pat to sign my form". Read one name at a time, the work's doer was the first
(or the last) name and the others were dropped: a paper that needed two signatures came back
with one, and the requester was told it was done.

A group is colleagues named as a list ("A and B", "A, B and C") or one after another ("by A,
then by B", "A and then B"), by name only, one of whom the clause reads as the doer of the
work (``Roles.actor``), while none of them receives, is taken from or gets the thing back in
it. Each of them does the work, in the order said: one task per doer (``each_doer``). The
paper comes back to its owner between two signatures, so every hand-over is the owner's own
and each signer sees it from them; a chain from signer to signer would hand one colleague's
paper to another without the owner between.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.joined_recipients import chains
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import task_kinds
from assistantx.core.task_schema import Task

# The words between two doers said one after the other: "A and B", "A, then B", "by A and
# then by B" (a comma alone joins only inside a list that ends with one of these)
_JOINS = frozenset(
    {("and",), ("then",), ("and", "then"), ("and", "by"), ("then", "by"), ("and", "then", "by")}
)


def joined_doers(
    tokens: Sequence[Token],
    ms: Sequence[Mention],
    actors: Sequence[str],
    busy: Sequence[str],
) -> list[tuple[str, ...]]:
    """The groups of colleagues joined as the doers of a clause's work, each in the order
    said: a list of names one of which is among ``actors``; ``busy``: the people the clause
    gives another role (a recipient, a source), whose list is no group of doers."""
    said = [m for m in ms if m.kind != "word"]
    groups: list[tuple[str, ...]] = []
    for run in chains(said, tokens, party=_one_person, join=_join):
        people = tuple(dict.fromkeys(said[k].ids[0] for k in run))
        if len(people) < 2 or not set(people) & set(actors) or set(people) & set(busy):
            continue
        groups.append(people)
    return groups


def _one_person(m: Mention, tokens: Sequence[Token]) -> bool:
    """A single named colleague, never "me": the requester does no work for themself."""
    del tokens
    return m.kind == "person" and len(m.ids) == 1 and not m.possessive


def _join(tokens: Sequence[Token], a: Mention, b: Mention) -> str:
    """ "and" when two mentions are joined by and/then words, "," by a pause alone, else ""."""
    between = tuple(t.word for t in tokens[a.end : b.start])
    if between in _JOINS:
        return "and"
    if not between and tokens[b.start].after_pause and not tokens[b.start].opens:
        return ","
    return ""


def each_doer(made: Sequence[Task], doers: Sequence[Sequence[str]]) -> list[Task]:
    """The tasks with a person's work done by each of its group of doers, one task each, in
    the order they were named; tasks of other kinds, or whose doer is in no group, as
    they are."""
    out: list[Task] = []
    for task in made:
        group = next((g for g in doers if task.actor in g), None)
        if group is None or task.kind not in task_kinds.person_kinds():
            out.append(task)
            continue
        out += [task.model_copy(update={"actor": who}) for who in group]
    return [t for n, t in enumerate(out) if t not in out[:n]]
