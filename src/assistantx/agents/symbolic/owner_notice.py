"""The requester is told first when another person's own yes is needed.

"can I borrow Page's kick stool?": the robot must not move before Page agrees (their yes in
their own chat, runtime/consent.py), and the requester should not be left wondering why
nothing happens or learn of it only from the outcome. So the first time the assistant asks a
named owner about their own item, the requester gets one line before the question goes out:
"I'll ask Page Ruiz first whether you may borrow their kick stool; nothing moves until they
say yes." Names and item names only, never ids.
"""

from __future__ import annotations

from assistantx.agents.symbolic.evidence import Evidence
from assistantx.agents.symbolic.roles import Role
from assistantx.core.office import Office
from assistantx.core.wording import item_type_name, person_name

# The roles whose person hands over their own item, and what the beneficiary may then do.
_MAY = {"lend": "borrow", "give": "have", "allow": "have"}


def owner_notice(office: Office, role: Role, person: str) -> str | None:
    """What the requester is told before ``person`` is asked for their own item in ``role``
    (None: not such a question: a guard, a signer, a recipient, or the requester's own)."""
    may = _MAY.get(role.kind)
    if may is None or role.item_type is None or person == role.requester:
        return None
    owner = role.item_owner or role.fixed
    if owner is None or owner != person or not office.is_person(owner):
        return None
    if office.is_supply(f"{role.item_type}:{owner}"):
        return None  # owned by nobody: no one's yes
    beneficiary = role.beneficiary or role.requester
    who = "you" if beneficiary == role.requester else person_name(office, beneficiary)
    thing = item_type_name(office, role.item_type)
    return (
        f"I'll ask {person_name(office, owner)} first whether {who} may {may} their {thing}; "
        "nothing moves until they say yes."
    )


def told(ev: Evidence, text: str) -> bool:
    """Whether the requester was already told ``text`` in this instruction."""
    return any(
        t.direction == "out" and t.person == ev.requester and t.text == text for t in ev.outbound
    )
