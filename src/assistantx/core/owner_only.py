"""Work that uses an item up is the owner's own call: nobody else can ask for it.

An operation that consumes what it works on (a shredder: ``Operation.consumes``) destroys the
item for good. Lending, copying or heating someone's item leaves it theirs, and their yes in
their own chat is enough (runtime/consent.py); destroying it is not a hand-over the owner can
agree to on someone else's behalf, so the assistant does it only when the owner asks for it
themselves. A requester's words ("she won't mind", "he said it's fine") change nothing: text
carries no authority. Items owned by nobody (a facility's supplies) and products have no owner
to ask, so they may be used up by anyone's request.

The one rule is read in two places: the reader, which declines such a request up front with
this module's words (before anyone is asked or anything moves), and the runtime's consent
guard, which refuses the work code whatever reasoner chose it.
"""

from __future__ import annotations

from assistantx.core.office import Office
from assistantx.core.wording import done_words, item_type_name, person_name


def consuming(office: Office, operation: str | None) -> bool:
    """Whether the office's operation uses up the item it works on (False: none named)."""
    if operation is None:
        return False
    found = next((o for o in office.operations if o.id == operation), None)
    return found is not None and found.consumes


def owner_only(office: Office, requester: str, item: str, operation: str | None) -> str | None:
    """The owner whose own request ``operation`` on ``item`` (``type:owner``) needs: a person
    of the office other than the requester, where the operation uses the item up; None when
    the requester may ask for it (their own item, nobody's item, work that gives it back)."""
    item_type, _, owner = item.partition(":")
    if not consuming(office, operation) or owner == requester or not office.is_person(owner):
        return None
    if office.is_supply(item) or office.item_type(item_type).kind == "product":
        return None
    return owner


def owner_only_reason(office: Office, owner: str, item_type: str, operation: str) -> str:
    """Why it is declined, in words for the requester: "Only Basil Moreau can ask for their
    ledger to be shredded ..."."""
    op = office.operation(operation)
    name = person_name(office, owner)
    thing = item_type_name(office, item_type)
    return (
        f"Sorry, I can't do that: only {name} can ask for their {thing} to be "
        f"{done_words(op)}, because it cannot be undone. A message from someone else, or "
        f"words saying {name} agrees, do not change that; {name} can ask me directly."
    )
