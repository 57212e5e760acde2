"""A failed action is a fact: recognise the same failure again, and say in words what it left.

The loop lets a reasoner retry a failed action once (an obstacle may have gone, a person may
answer now). When the same action fails again for the same reason (the same error class),
repeating it is pointless: the loop ends the instruction and the requester gets a summary
that says what failed, where the robot is, what the locker holds and what happens to it. The
text uses names, never ids.
"""

from __future__ import annotations

import math

from assistantx.core import wording
from assistantx.core.actions import Action, Move
from assistantx.core.office import Office
from assistantx.core.ports.robot import RobotBase
from assistantx.core.trace import ActionResult
from assistantx.memory.short_term import ShortTermMemory

# The robot's errors in words a person reads (their messages carry map coordinates).
_REASONS = {
    "BlockedError": "something blocks the way",
    "DoorClosedError": "a door on the way is closed",
    "LocalizationLostError": "the robot lost track of where it is",
    "UnreachableError": "there is no way there on the map",
}


# What happens next when the way to a place is shut (the robot tried its recoveries first).
_WAY_CLOSED = {
    "DoorClosedError": (
        "The door on the way to {place} is closed and there is no other way in. I will not "
        "try again by myself: once the door is open, send me the request again and I'll go."
    ),
    "BlockedError": (
        "Something stands in every way to {place}; I tried going round, turning, backing up "
        "and waiting. Once the way is clear, send me the request again and I'll go."
    ),
}


class FailureMemory:
    """The error class of each action signature's last failure. Only adapter errors count
    (a drive that was blocked, a lock that did not answer): a wait that timed out is not an
    error, and waiting again later may well be the right thing to do."""

    def __init__(self) -> None:
        self._last: dict[str, str] = {}

    def repeated(self, result: ActionResult) -> bool:
        """Record a failed result; True if the same action already failed the same way."""
        if result.error is None:
            return False
        signature = result.action.signature()
        reason = result.error
        again = self._last.get(signature) == reason
        self._last[signature] = reason
        return again


def place_name(office: Office, place: str) -> str:
    """The office's name of a place; one it does not know is "the destination", never an id."""
    return wording.place_name(office, place, unknown="the destination")


def item_name(office: Office, item_id: str) -> str:
    type_id, _, owner_id = item_id.partition(":")
    kind = next((t.name for t in office.item_types if t.id == type_id), "item")
    owner = next((p.name for p in office.people if p.id == owner_id), None)
    return f"{owner}'s {kind}" if owner else f"the {kind}"


def robot_whereabouts(office: Office, robot: RobotBase) -> str:
    """ "at the Mail room", or "near the Mail room" when it stopped between places."""
    state = robot.state()
    if state.place is not None:
        return f"at {place_name(office, state.place)}"
    if not office.locations:
        return f"at ({state.pose.x:.1f}, {state.pose.y:.1f})"
    nearest = min(
        office.locations, key=lambda loc: math.hypot(loc.x - state.pose.x, loc.y - state.pose.y)
    )
    return f"near {nearest.name}"


def _failed_action_in_words(office: Office, action: Action) -> str:
    """ "I could not ask Wang Fang": what failed, with names, never an action's wire name."""
    if isinstance(action, Move):
        return f"I could not get to {place_name(office, action.place)}"
    contact = getattr(action, "contact", None) or getattr(action, "target", None)
    who = (
        wording.person_name(office, contact, unknown="them") if isinstance(contact, str) else "them"
    )
    doing = {
        "inquire": f"ask {who}",
        "inform": f"send {who} a message",
        "send_qr": f"send {who} a locker code",
        "forward_file": f"forward the file to {who}",
        "wait_in_place": f"complete the hand-over with {who}",
    }.get(action.type, "finish a step")
    return f"I could not {doing}"


def failure_summary(
    office: Office, stm: ShortTermMemory, robot: RobotBase, result: ActionResult
) -> str:
    action: Action = result.action
    what = _failed_action_in_words(office, action)
    reason = _REASONS.get(result.error or "", result.observation.removeprefix("failed: "))
    lines = [f"{what}, twice for the same reason ({reason}), so I stopped trying."]
    if isinstance(action, Move) and result.error in _WAY_CLOSED:
        lines.append(_WAY_CLOSED[result.error].format(place=place_name(office, action.place)))
    where = robot_whereabouts(office, robot)
    contents = stm.embodied.locker_contents
    if contents:
        items = ", ".join(item_name(office, i) for i in contents)
        lines.append(
            f"The robot is {where}; {items} {'is' if len(contents) == 1 else 'are'} locked in "
            "its locker. It will wait there with the locker closed until someone clears the "
            "way or collects the contents with a locker code."
        )
    else:
        lines.append(f"The robot is {where}; its locker is empty.")
    return " ".join(lines)


# Why the consent guard refused a hand-over, in words for the requester (the guard's own
# reason, written for the agent, carries ids).
_REFUSED_BECAUSE = {
    "not_a_party": (
        "{who} is not someone you named to receive or work on it, and I hand things only to "
        "you, their owner, whoever keeps them, or a person you name"
    ),
    "no_answer": "{who} has not answered me, so they have not agreed to the hand-over",
    "no_consent": "its owner has not given me their own yes",
    "owner_only": "it would be used up, and only its owner can ask for that themselves",
}


def refusal_summary(office: Office, result: ActionResult, requester: str) -> str:
    """What the requester reads when the reasoner tried again, unchanged, an action the consent
    guard refused: what could not be done and why, with names, and what would unblock it."""
    action: Action = result.action
    what = _failed_action_in_words(office, action)
    contact = getattr(action, "contact", None) or getattr(action, "target", None)
    who = (
        wording.person_name(office, contact, unknown="them") if isinstance(contact, str) else "they"
    )
    item = getattr(action, "item", None) or getattr(action, "file", None)
    if isinstance(item, str):
        type_id, _, owner = item.partition(":")
        kind = next((t.name for t in office.item_types if t.id == type_id), "item")
        what += f" for your {kind}" if owner == requester else f" for {item_name(office, item)}"
    why = _REFUSED_BECAUSE.get(result.error or "", "the hand-over was not allowed")
    return (
        f"{what}: {why.format(who=who)}. I will not try the same thing again; if someone else "
        "should do it, tell me who and send the request again."
    )
