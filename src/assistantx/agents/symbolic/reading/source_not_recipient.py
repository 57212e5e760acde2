"""The one a thing is taken from ("from Pat") is not whom it goes to, and hands it over.

"take it from Pat to her", "bring the ruler over from Ken for him": a thing is carried from
one person to another, so "her" is not the colleague the clause names as the source; of the
colleagues named before, the one left is meant ("Ms Okafor needs her tape back, can you take
it from Pat to her": Ms Okafor). "back to her" may be the one it came from ("borrow it from Pat
and take it back to her"), so a pronoun after "back" keeps every colleague.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core.office import Office
from assistantx.core.task_schema import Task

_BACK = frozenset({"back"})


def not_the_source(
    others: Sequence[str], sources: Sequence[str], tokens: Sequence[Token], at: int
) -> list[str]:
    """``others`` (the colleagues a receiving pronoun at token ``at`` may mean) without the
    clause's ``sources`` said before it, unless the pronoun gives a thing back."""
    before = [t.word for t in tokens[max(0, at - 2) : at]]
    if not sources or set(before) & _BACK:
        return list(others)
    return [x for x in others if x not in sources]


def taken_from(office: Office, task: Task, sources: Sequence[str]) -> Task:
    """A thing going back to its owner ("Ms Okafor needs her tape back") that the request
    takes from one colleague ("from Pat"): that colleague hands over the one they have. The
    office file knows only the things it lists, so it is theirs to hand over (as "take the
    tape from Pat to May" reads), asked of them; where that colleague has no such thing of
    their own, the owner's, which they have now (the source). Unchanged where the thing
    already has a holder, or several or no colleague is taken from."""
    found = set(sources)
    if task.kind != "transfer" or task.item is None or len(found) != 1:
        return task
    if task.owner is None or task.owner != task.recipient or task.source is not None:
        return task
    giver = next(iter(found))
    if giver == task.owner:
        return task
    if giver not in office.owners_of(task.item):
        # "Rose wants her umbrella back, take it from Pat to her" where the office lists no
        # umbrella of Pat's: Rose's own, which Pat has now (as a lent thing said to be on
        # someone's desk is taken from them), never a question whether Rose should get it
        return task.model_copy(update={"source": giver})
    return task.model_copy(update={"owner": giver})
