"""The simulated world's snapshot names every held code as it is now and everyone told, at
every checkpoint, though its unchanged parts are not built again."""

from __future__ import annotations

import json

from assistantx.core.office import load_office
from assistantx.service.colleagues import code_ref, snapshot
from assistantx.sim.office import HeldCode, SimOffice


def test_the_snapshot_follows_the_codes_and_who_was_told() -> None:
    sim = SimOffice(load_office())
    code = HeldCode("ins-1", "wang", "payload-1", "deposit", "stapler:wang", told="put it in")
    sim.codes = [code]
    sim.told = {("ins-1", "wang"), (None, "lee")}
    first = snapshot(sim)
    assert first["codes"] == [
        {
            "instruction_id": "ins-1",
            "person": "wang",
            "purpose": "deposit",
            "item": "stapler:wang",
            "told": "put it in",
            "scheduled": False,
            "done": False,
            "complained": False,
            "ref": code_ref("payload-1"),
        }
    ]
    assert json.loads(json.dumps(first["told"])) == [["", "lee"], ["ins-1", "wang"]]
    first["codes"][0]["done"] = "changed by a reader"  # a snapshot is the caller's own
    code.done = True  # the code was used since
    sim.told.add(("ins-2", "zhang"))
    again = snapshot(sim)
    assert again["codes"][0]["done"] is True
    assert [list(t) for t in again["told"]] == [["", "lee"], ["ins-1", "wang"], ["ins-2", "zhang"]]
    sim.told = {("ins-2", "zhang")}  # an instruction ended: its entries dropped
    assert [list(t) for t in snapshot(sim)["told"]] == [["ins-2", "zhang"]]
