"""What a request said of whose a thing is and who gets it, kept through the answers to the
questions it raised. "Can you give Fiona my stapler and have the Boss sign my form?" answered
"The stapler." was re-read with the answer as anyone's stapler brought to the requester, and
"Bring me Brook's charger, ..." answered "The charger." as anyone's charger: the re-read lost
the owner and the recipient the request itself named, and was acted on.

The request's own words say (``said_roles``): the owner of each thing it names with a
possessive ("my stapler": the requester; "Brook's charger": Brook), and the colleagues it
hands something to (a handing verb's first object, "give Fiona ...", or "to Fiona" after the
thing). A reading after an answer that gives such a thing another owner, or hands nothing to
a colleague the request handed something to, contradicts the request (``contradicts``): it
is never acted on, and the question stays open. What the answer itself says ("Olive's
charger, sorry") counts as said too.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.core import english
from assistantx.core.task_schema import TaskFrame

_HANDING = english.words("dative_verbs") | english.words("handing_verbs")
_TO = frozenset({"to"})


@dataclass
class Roles:
    """Owners said of item types, and the colleagues said to get something."""

    owners: dict[str, set[str]] = field(default_factory=dict)
    recipients: set[str] = field(default_factory=set)


def said_roles(lexed: Sequence[Lexed], requester: str) -> Roles:
    """The owners and recipients ``lexed`` (the request, then the answers) say."""
    roles = Roles()
    for said in lexed:
        mentions, tokens = said.mentions, said.tokens
        for n, m in enumerate(mentions[:-1]):
            after = mentions[n + 1]
            if m.possessive and after.kind == "item" and after.start == m.end:
                owner = requester if m.kind == "self" else m.ids[0] if m.kind == "person" else None
                if owner is not None and (m.kind == "self" or len(m.ids) == 1):
                    roles.owners.setdefault(after.ids[0], set()).add(owner)
        for n, m in enumerate(mentions):
            if m.kind != "person" or m.possessive or len(m.ids) != 1 or n == 0:
                continue
            before = mentions[n - 1]
            handed = before.kind == "cue" and tokens[before.start].word in _HANDING
            to = (
                before.kind == "word"
                and tokens[before.start].word in _TO
                and n >= 2
                and mentions[n - 2].kind in ("item", "pronoun")
            )
            if handed or to:
                roles.recipients.add(m.ids[0])
    roles.recipients.discard(requester)
    return roles


def contradicts(frame: TaskFrame, roles: Roles) -> bool:
    """Whether ``frame``'s tasks give a thing another owner than the one said, or hand
    nothing to a colleague the request said gets something."""
    for task in frame.tasks:
        owners = roles.owners.get(task.item or "")
        if owners and task.owner not in owners:
            return True
    people = {p for t in frame.tasks for p in (t.recipient, t.actor, t.owner) if p}
    return bool(roles.recipients - people)
