"""An office's own operation whose id is also a built-in kind of work by hand ("seal": a
kitchen's vacuum sealer, where the default office's "seal" is a person's stamp) is run by the
facility's keeper: the simulated colleague no longer answers "Sorry, I can't help with that
(seal)" because the id was read as the kind before the office's operations."""

from __future__ import annotations

from typing import Any

from assistantx.core.office import Office, parse_office
from assistantx.sim.people import can_do
from assistantx.sim.world import World
from helpers.airside_kitchen import raw_airside_kitchen


def _sealing_office() -> Office:
    raw: dict[str, Any] = raw_airside_kitchen()
    for op in raw["operations"]:
        if op["id"] == "vac_seal":
            op["id"] = "seal"
    for facility in raw["facilities"]:
        ops = facility.get("operations", [])
        facility["operations"] = ["seal" if o == "vac_seal" else o for o in ops]
    return parse_office(raw, "sealing kitchen")


def test_the_sealers_keeper_can_run_an_operation_named_like_a_kind() -> None:
    world = World.from_office(_sealing_office())
    assert can_do(world, "maren", "seal")  # she keeps the vacuum sealer
    assert not can_do(world, "odile", "seal")  # she keeps no sealer and owns no stamp


def test_a_keeper_of_another_facility_still_cannot() -> None:
    world = World.from_office(_sealing_office())
    assert can_do(world, "maren", "chill")
    assert not can_do(world, "ines", "chill")
