"""A long-running simulated office keeps a bounded, recent history.

The service runs one SimOffice for as long as it serves: what it keeps of its messages,
ended instructions and world events must stop growing early (bench/instructions_10k.py
measures the served process's memory from its 1,000th instruction on)."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office, load_office
from assistantx.core.ports.messenger import ChatRef
from assistantx.sim.office import KEEP, SimOffice
from assistantx.sim.world import LOG_KEEP


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


def test_messages_people_wrote_keep_the_newest(office: Office) -> None:
    sim = SimOffice(office)
    chat = ChatRef(kind="dm", id="lee")
    for i in range(3 * KEEP):
        sim.messenger.post("lee", chat, f"message {i}")
    kept = sim.messenger.received
    assert KEEP <= len(kept) <= 2 * KEEP
    assert kept[-1].text == f"message {3 * KEEP - 1}"
    assert [m.text for m in kept] == [f"message {i}" for i in range(3 * KEEP - len(kept), 3 * KEEP)]


def test_ended_instructions_and_their_requesters_keep_the_newest(office: Office) -> None:
    sim = SimOffice(office)
    for i in range(3 * KEEP):
        sim.register_instruction(f"ins-{i}", "lee")
        sim.end_instruction(f"ins-{i}")
    assert KEEP <= len(sim.ended) <= 2 * KEEP
    assert f"ins-{3 * KEEP - 1}" in sim.ended and "ins-0" not in sim.ended
    assert len(sim.requesters) <= 2 * KEEP and "ins-0" not in sim.requesters


def test_world_events_keep_the_newest(office: Office) -> None:
    world = SimOffice(office).world
    for i in range(3 * LOG_KEEP):
        world.note(float(i), "item_moved", item="stapler:zhang", n=i)
    assert LOG_KEEP <= len(world.log) <= 2 * LOG_KEEP
    assert world.log[-1].detail["n"] == 3 * LOG_KEEP - 1
