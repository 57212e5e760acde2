""" "one from Mark": the pro-form "one" stands for the thing named before ("Mrs Okafor needs
a ruler, can you take one from Mark to her"), and "from" a colleague right after it says
whose, as "a ruler from Mark" does: Mark's ruler, asked of Mark, not anyone's. Only a
colleague named alone right after "one from" counts ("one from Mark or Joy" leaves the choice
open; "one from the kitchen" names a place, no owner)."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core.task_schema import Task

# The pro-forms of a noun said before ("one", "another"): a count of that thing.
_ONE = frozenset({"one", "another"})
# What may join a second person to the first ("from Mark or Joy"): then no one owner.
_JOINS = frozenset({"or", "and"})


def one_from(tokens: Sequence[Token], mentions: Sequence[Mention]) -> str | None:
    """The one colleague a clause's "one from <colleague>" names, or None."""
    for m in mentions:
        if m.kind != "person" or len(m.ids) != 1 or m.possessive or m.start < 2:
            continue
        if tokens[m.start - 1].word != "from" or tokens[m.start - 2].word not in _ONE:
            continue
        if m.end < len(tokens) and tokens[m.end].word in _JOINS:
            continue  # "one from Mark or Joy": either
        return m.ids[0]
    return None


def owned_as_one_from(task: Task, giver: str | None) -> Task:
    """A transfer of nobody's thing in particular that the clause takes "one from" a
    colleague: that colleague's, as "a ruler from Mark" is (unless it goes to them)."""
    if giver is None or task.kind != "transfer" or task.owner is not None:
        return task
    if task.item is None or task.recipient == giver or task.source is not None:
        return task
    return task.model_copy(update={"owner": giver})
