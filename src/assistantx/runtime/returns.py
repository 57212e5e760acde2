"""Nobody is left without their things: an instruction that ends without success while
someone's item is in the robot's locker (cancelled, failed, past its deadline) gives it back.

The errand runs after the instruction ended, as a task of its own under the errand's id
(``<instruction>.return``): it takes the robot's body lease, drives to the owner, tells them in
words why their item comes back, sends them a one-time code to take it out and waits for
them. The requester's final message already says the item goes back (``return_note``). A
shutdown cancels the errand like any running work; the service journals the errands still to
do and starts them again on its next start (``attempt`` counts those starts): each attempt
tells the owner again and sends a code of its own (the start-up withdrew the code of the
attempt that was cut short); a step journaled as sent within one attempt is not sent twice.
"""

from __future__ import annotations

import logging

from assistantx.core.actions import Action, Inform, Move, SendQR, WaitInPlace
from assistantx.core.office import Office
from assistantx.core.wording import item_phrase, person_name
from assistantx.memory.resolve import Resolver
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.executors import Executor
from assistantx.runtime.fleet import FleetLease
from assistantx.runtime.lease import BodyLease

logger = logging.getLogger(__name__)

RETURN_WAIT_S = 600.0  # how long the robot waits at the owner's place (office clock)


def items_to_return(office: Office, stm: ShortTermMemory) -> list[tuple[str, str]]:
    """(item, owner) for each item in the locker, by this instruction's account, that it
    ends holding without having delivered it; empty when the instruction succeeded."""
    if stm.trace.outcome == "done":
        return []
    people = {p.id for p in office.people}
    aboard: list[tuple[str, str]] = []
    for item in stm.embodied.locker_contents:
        owner = item.partition(":")[2]
        if owner in people:
            aboard.append((item, owner))
    return aboard


def return_note(office: Office, stm: ShortTermMemory) -> str:
    """For the requester's final message: what goes back to whom, in words ("" if nothing)."""
    aboard = items_to_return(office, stm)
    if not aboard:
        return ""
    you = stm.requester
    parts = [
        f"{item_phrase(office, item, you=you)} back to {person_name(office, owner, you=you)}"
        for item, owner in aboard
    ]
    return f" The robot is bringing {_and(parts)}."


async def return_items(
    office: Office,
    resolver: Resolver,
    executor: Executor,
    lease: BodyLease | FleetLease,
    ended: ShortTermMemory,
    *,
    attempt: int = 0,
) -> None:
    """Bring each item back to its owner (see the module's docstring)."""
    aboard = items_to_return(office, ended)
    if not aboard:
        return
    errand_id = f"{ended.instruction_id}.return"

    def errand_for(owner: str, item: str) -> ShortTermMemory:
        # The errand acts for the owner: they are given back their own item, which needs no
        # one's consent (runtime/consent.py lets a code go to the requester), and nobody else
        # can be handed anything by it.
        stm = ShortTermMemory.begin(
            errand_id,
            owner,
            f"give back what {ended.instruction_id} left in the locker",
            trace_text="return items",
            reasoner="return",
            started_at=executor.ctx.clock.now(),
        )
        stm.embodied.locker_contents = [item]
        return stm

    errands: list[ShortTermMemory] = []
    why = _why(ended)
    await lease.acquire(errand_id)
    try:
        for n, (item, owner) in enumerate(aboard):
            stm = errand_for(owner, item)
            errands.append(stm)
            thing = item_phrase(office, item, you=owner)
            requester = person_name(office, ended.requester, you=owner)
            steps: list[Action] = [
                Move(place=owner),
                Inform(
                    contact=owner,
                    content=(
                        f"{thing[0].upper()}{thing[1:]} is in the robot's locker, and "
                        f"{requester}'s request it was for {why}. The robot is at your desk "
                        "to give it back: scan the code I am sending you to take it out."
                    ),
                ),
                SendQR(contact=owner, item=item, purpose="collect"),
                WaitInPlace(person=owner, timeout_s=RETURN_WAIT_S),
            ]
            for m, action in enumerate(steps):
                grounded = resolver.ground(action)  # the owner's name → their desk
                key = f"r{n}a{m}"
                if attempt and isinstance(action, Inform | SendQR):
                    # A fresh code (the last attempt's was withdrawn), and the words that
                    # say what it is for.
                    key += f".{attempt}"
                result = await executor.execute(stm, grounded, key=key)
                if not result.ok:
                    logger.warning(
                        "returning %s to %s: %s failed: %s",
                        item,
                        owner,
                        action.type,
                        result.observation,
                    )
                    break
    finally:
        for stm in errands:
            await executor.revoke_codes(stm)
        executor.forget(errand_id)
        lease.release(errand_id)


def _why(stm: ShortTermMemory) -> str:
    if stm.trace.cancelled:
        return "was cancelled"
    if "out of time" in (stm.trace.summary or ""):  # the loop's words for a deadline
        return "ran out of time"
    return "could not be completed"


def _and(parts: list[str]) -> str:
    if len(parts) == 1:
        return parts[0]
    return ", ".join(parts[:-1]) + f" and {parts[-1]}"
