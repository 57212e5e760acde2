"""The keeper asked to "run it" names the work on the requester's thing: "need an ABV on my
sample before we can it tomorrow, can zosia run it", where the office has no word for what an
ABV is.

The need's own noun ("an ABV", "a reading") may be no word of the office, so the work is not
read from it and the request was taken for the sample alone (whom to give it to, asked). But
the colleague asked to "run it" (``work_pro_verb``) keeps a facility, and the requester's own
thing the message names ("my sample") is what one of that facility's operations works on:
the keeper is asked to do that operation on it, as "can Zosia test my sample" asks. Only
where the message says a need ("need ..."), exactly one colleague is so asked, the message
names exactly one thing of the requester's, and exactly one operation of the facilities the
colleague keeps takes that kind of thing; anything else keeps the reader's own question.
"""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.agents.symbolic.reading.named_maker import asked_colleagues
from assistantx.agents.symbolic.reading.work_pro_verb import work_referred_to
from assistantx.core import english
from assistantx.core.office import Office, Operation

# "need an ABV on my sample": the need that says some work is wanted on the thing
_NEEDS = english.words("need_verbs")


def keeper_asked_work(office: Office, whole: Lexed, requester: str) -> str | None:
    """The request said plainly ("can Zosia test my beer sample") where the message asks a
    keeper to "run it" on the requester's one thing their facility works on; None where it
    does not (see the module)."""
    asked = asked_colleagues(whole, requester, lambda at: work_referred_to(whole.tokens, at))
    if len(asked) != 1:
        return None
    if not any(t.word in _NEEDS for t in whole.tokens):
        return None  # "got my badge here, can Max sort it": no work said to be needed
    keeper = next(iter(asked))
    own = _own_things(whole)
    if len(own) != 1:
        return None
    item = next(iter(own))
    ops = _operations_on(office, keeper, item)
    if len(ops) != 1 or not ops[0].verbs:
        return None
    name = office.person(keeper).name
    return f"can {name} {ops[0].verbs[0]} my {office.item_type(item).name}"


def _own_things(whole: Lexed) -> set[str]:
    """The item types the message names as the requester's own ("my sample")."""
    ms = whole.mentions
    return {
        i
        for n, m in enumerate(ms)
        if m.kind == "item"
        and n > 0
        and ms[n - 1].kind == "self"
        and ms[n - 1].possessive
        and ms[n - 1].end == m.start
        for i in m.ids
    }


def _operations_on(office: Office, keeper: str, item: str) -> list[Operation]:
    """The operations of the facilities ``keeper`` keeps that work on an ``item``."""
    found = {
        op_id
        for f in office.facilities
        if keeper in f.guards
        for op_id in f.operations
        if office.operation(op_id).input == item
    }
    return [office.operation(o) for o in sorted(found)]
