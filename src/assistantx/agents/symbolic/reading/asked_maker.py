"""The colleague asked to make one is its maker, not whom it is for: "I need a coffee. can
Gao knock one up?", "I'm parched, could Sun whip one up?".

After a clause that asks for a product (a need, "a coffee please"), a clause whose subject is
a colleague after a request's modal ("can Gao ...") and whose verb makes a thing ("make",
"knock up", "whip up", "sort out") with "one" as its object asks that colleague to make the
product just asked for. The product still goes to whom the earlier clause said; the colleague
is its maker where they keep a facility that makes it (else the parser's ``named_maker`` says
they don't and asks before the keepers make it). Read as "bring Gao one", the coffee would be
handed to the maker: a wrong physical action. Someone named after the verb is still whom it is
for ("can you make Gao one")."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading._parties import Clause
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english
from assistantx.core.office import Office
from assistantx.core.task_schema import Task

_MAKING = english.words("making_verbs")
_REQUEST_MODALS = english.words("request_modals")


def asked_maker(
    office: Office,
    tasks: Sequence[Task],
    clause: Clause,
    tokens: Sequence[Token],
    made: Sequence[Task],
) -> Task | None:
    """The last task, a product, with the colleague the clause asks to make "one" as its
    maker (where they keep a facility that makes it); None when the clause is no such ask.
    ``made``: the clause's own tasks, at most the same product again ("pour one" reads as a
    product of its own), which the maker's ask replaces."""
    if not tasks:
        return None
    last = tasks[-1]
    if last.kind != "produce" or last.owner is not None or last.item is None:
        return None
    if any(t.kind != "produce" or t.item not in (last.item, None) for t in made):
        return None  # a work of its own ("can Gao print one"), read as said
    mentions = clause.mentions
    for n, m in enumerate(mentions[:-2]):
        if m.kind != "person" or len(m.ids) != 1 or m.possessive:
            continue
        if m.start == 0 or tokens[m.start - 1].word not in _REQUEST_MODALS:
            continue  # only the subject of a request's modal is asked to do it
        verb = mentions[n + 1]
        if verb.start != m.end or tokens[verb.start].word not in _MAKING:
            continue
        end = _one_of(mentions, n + 2, verb.end, tokens, last.item)
        if end is None:
            continue  # "can Gao make Sun one": Sun is whom it is for
        if any(x.kind in ("person", "item") for x in mentions[end:]):
            continue  # "... one for Sun": someone else's, read as said
        maker = m.ids[0]
        return last.model_copy(update={"actor": maker if _keeps(office, maker, last) else None})
    return None


def _keeps(office: Office, person: str, task: Task) -> bool:
    """Whether ``person`` keeps a facility whose operation makes the task's product."""
    for op in office.operations:
        if op.product != task.item:
            continue
        for f in office.facilities:
            if op.id in f.operations and person in f.guards:
                return True
    return False


_ARTICLES = frozenset({"a", "an"})


def _one_of(
    mentions: Sequence[Mention], k: int, at: int, tokens: Sequence[Token], item: str
) -> int | None:
    """Where the verb's object ends, as a mention index, when it is "one" (or "a <the
    product>", as an earlier stage spells "one" out) starting at token ``at``, from mention
    ``k`` on; None when the object is something else."""
    if at < len(tokens) and tokens[at].word == "one":
        return k + 1 if k < len(mentions) and mentions[k].start == at else None
    if at < len(tokens) and tokens[at].word in _ARTICLES:
        at += 1
    for j in range(k, len(mentions)):
        m = mentions[j]
        if m.start < at:
            continue  # the article itself, where it is a mention
        if m.start == at and m.kind == "item" and m.ids == (item,) and not m.possessive:
            return j + 1
        return None
    return None
