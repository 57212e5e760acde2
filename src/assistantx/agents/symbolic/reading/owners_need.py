"""A colleague's thing said to need one of the office's services goes back to its owner:
"Olek's 4-gas is due a bump test", "Zhang's contract needs copying". The need is the
thing's, said of its owner's thing, not the speaker's want; read with the speaker as the
one it comes back to, the colleague's monitor (and the contract with its copy) ended up at
the speaker's desk. The speaker who wants it says so ("... for me", "... bring it to me",
"I need ..."), and a request's own verb ("copy Zhang's contract") is the speaker's want as
before, as is a statement followed by the speaker's own request about the thing ("Lee's
lunch needs heating, sort it pls"). Either way the owner is asked before their thing is
taken (the plan's consent)."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.possessed_thing import possessed
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core.task_schema import Task

# "needs a bump test", "need copying" (and "is due ..." read so: ``due_service``)
_NEEDS = frozenset({"needs", "need"})
# the speaker's own want said beside it ("for me", "bring it to me", "I need it")
_SPEAKER = frozenset({"me", "i", "my", "mine", "myself", "im", "ill", "id"})


def back_to_owner(
    task: Task, tokens: Sequence[Token], mentions: Sequence[Mention], requester: str
) -> Task:
    """``task`` with its owner as the one it comes back to, when the request says the
    owner's thing needs the work and the speaker asks for nothing of it themselves."""
    if task.kind == "transfer" or task.item is None or task.owner in (None, requester):
        return task
    if task.recipient != requester or task.destination is not None:
        return task
    if any(t.word in _SPEAKER for t in tokens):
        return task
    for n, m in enumerate(mentions):
        if m.kind != "person" or not m.possessive or m.ids != (task.owner,):
            continue
        thing = possessed(tokens, mentions, n)
        if thing is None or thing.kind != "item":
            continue
        if thing.end >= len(tokens) or tokens[thing.end].word not in _NEEDS:
            continue
        if any(p.kind == "pronoun" and p.start > thing.end for p in mentions):
            # "Lee's lunch needs heating, sort it pls": a request of the speaker's own about
            # it follows, theirs to have back (as the default office's tests assert)
            return task
        return task.model_copy(update={"recipient": task.owner})
    return task
