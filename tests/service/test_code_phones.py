"""The simulated people's phones keep each held code whole (with its payload), as it is now:
a field that changed since the last save is saved changed."""

from __future__ import annotations

import json
from pathlib import Path

from assistantx.service.colleagues import CodePhones, code_ref, held_payloads, phone_entries
from assistantx.sim.office import HeldCode


def _code(n: int) -> HeldCode:
    return HeldCode(
        instruction_id=f"ins-{n}",
        person="wang",
        payload=f"payload-{n}",
        purpose="deposit",
        item="stapler:wang",
        told="put it in the locker",
    )


def test_a_phone_keeps_each_code_whole_and_as_it_is_now(tmp_path: Path) -> None:
    codes = [_code(1), _code(2), HeldCode("ins-3", "lee", "", "collect", "stapler:wang")]
    entries = phone_entries(codes)
    assert list(entries) == [code_ref("payload-1"), code_ref("payload-2")]  # none without one
    assert json.loads(entries[code_ref("payload-1")]) == {
        "instruction_id": "ins-1",
        "person": "wang",
        "payload": "payload-1",
        "purpose": "deposit",
        "item": "stapler:wang",
        "told": "put it in the locker",
        "scheduled": False,
        "done": False,
        "complained": False,
    }
    codes[0].done = True  # used since: the phone says so at the next save
    assert json.loads(phone_entries(codes)[code_ref("payload-1")])["done"] is True
    phones = CodePhones(tmp_path / "sim-codes.json")
    phones.save(codes)
    assert phones.load() == phone_entries(codes)
    world = {"codes": []}  # a snapshot journaled before the codes reached the phones
    assert sorted(held_payloads(world, phones.load())) == ["payload-1", "payload-2"]
