"""Every text a person receives names people and things: no item ids (``stapler:wang``), no
instruction ids (``ins-…``), no internal role or purpose tokens (``lend:``, ``(stapler)``).

Runs every kind of instruction of ``test_tasks_in_sim`` (L1/L2/L3, unachievable, files,
combinations) in the simulated office and reads what the messenger sent: message texts and
the names of attached files.
"""

from __future__ import annotations

import re
from typing import get_args

import pytest
from symbolic_run import run_instruction
from test_tasks_in_sim import CASES, Case

from assistantx.agents.symbolic.roles import RoleKind
from assistantx.core import task_kinds
from assistantx.core.office import Office, load_office
from assistantx.sim.people import handover_problem
from assistantx.sim.world import World

_OFFICE = load_office()
_ITEM_TYPES = sorted({t.id for t in _OFFICE.item_types}, key=len, reverse=True)
_PEOPLE = sorted({p.id for p in _OFFICE.people}, key=len, reverse=True)
# stapler:wang, file:lee, copy:lee ... (the type, a colon, an owner id)
ITEM_ID = re.compile(rf"\b(?:{'|'.join(_ITEM_TYPES)}):(?:{'|'.join(_PEOPLE)})\b")
INSTRUCTION_ID = re.compile(r"\bins-[0-9a-z]+")
ROLE_KINDS = (*get_args(get_args(RoleKind)[0]), *(k.id for k in task_kinds.kinds()))
_LABELS = (*ROLE_KINDS, *task_kinds.purposes())
# An internal token used as a label ("lend: stapler", "(stapler)", "send_file").
TOKEN = re.compile(
    rf"\b(?:{'|'.join(_LABELS)}): (?:{'|'.join(_ITEM_TYPES)})\b"
    rf"|\((?:{'|'.join(_ITEM_TYPES)}|help)\)"
    r"|\b[a-z]+_[a-z_]+\b"
)


def offences(text: str) -> list[str]:
    return [m.group(0) for p in (ITEM_ID, INSTRUCTION_ID, TOKEN) for m in p.finditer(text)]


def test_the_patterns_catch_what_people_saw() -> None:
    assert offences("scan it to put stapler:wang into the locker") == ["stapler:wang"]
    assert offences("Forwarding file:lee from lee (instruction ins-3484ab).") == [
        "file:lee",
        "ins-3484ab",
    ]
    assert offences("hand-over with lend: stapler") == ["lend: stapler"]
    assert offences("stamp it with the seal: Mao Jun did not answer") == []
    assert sorted(offences("no one could send_file (file): Wang Fang did not answer")) == [
        "(file)",
        "send_file",
    ]
    assert offences("Hi Wang, could you lend Lee Ming your stapler?") == []


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
async def test_no_internal_ids_reach_people(office: Office, case: Case) -> None:
    run = await run_instruction(office, case.requester, case.text, unavailable=case.unavailable)
    assert run.sim.messenger.sent
    for message in run.sim.messenger.sent:
        read = [message.text, *(a.name for a in message.attachments)]
        for text in read:
            assert offences(text) == [], f"{message.chat.id} read: {text!r}"


@pytest.mark.parametrize(
    ("person", "purpose", "item", "place"),
    [
        ("zhang", "deposit", "stapler:wang", "desk_03"),  # not his to put in
        ("lee", "collect", "stapler:wang", "desk_03"),  # not in the locker
        ("zhang", "sign", "document:lee", "desk_05"),
        ("lee", "produce", "printout:lee", "print_room"),  # cannot print here
        ("mao", "produce", "printout:lee", "print_room"),  # never got the file
        ("mao", "produce", "copy:lee", "print_room"),  # the original is not there
        ("mao", "produce", "stapler:mao", "print_room"),
    ],
)
def test_what_simulated_people_say_at_the_locker_names_things(
    person: str, purpose: str, item: str, place: str
) -> None:
    """Their "I came to the robot, but: …" reaches the assistant and the chat views."""
    world = World.from_office(_OFFICE, ())
    problem = handover_problem(world, person, purpose, item, place)
    assert problem is not None
    assert offences(problem) == [], problem
