"""Office-format classes of blind round 4 (section b): a second transform operation at the
machine that copies (the code names the one asked for, and the product is that one's), a
seal tool whose type id is not "seal" (found by its ``seals`` property), and a consuming
service whose locker text does not say "put it back"."""

from __future__ import annotations

from typing import Any

from symbolic_run import run_instruction

from assistantx.core.actions import SendQR
from assistantx.core.office import DEFAULT_OFFICE, Office, load_office, parse_office
from assistantx.core.task_spec import BaseInstruction, Part
from assistantx.core.wording import purpose_text
from assistantx.evaluation.dataset.generate import _task, classify, verify_tasks
from assistantx.runtime import consent
from assistantx.runtime.consent import check
from helpers.consent_memory import answered, memory
from helpers.yaml_files import raw_yaml


def _raw() -> dict[str, Any]:
    raw: dict[str, Any] = raw_yaml(DEFAULT_OFFICE)
    return raw


def _copy_and_scan() -> Office:
    raw = _raw()
    raw["item_types"].append({"id": "scan", "name": "scan", "kind": "product"})
    raw["operations"].append(
        {"id": "scan", "name": "scan", "verbs": ["scan"], "input": "document", "product": "scan"}
    )
    for f in raw["facilities"]:
        if f["id"] == "printer":
            f["operations"].append("scan")
    return parse_office(raw)


async def test_a_scan_at_the_copier_makes_a_scan_not_a_copy() -> None:
    office = _copy_and_scan()
    run = await run_instruction(office, "lee", "Please scan my document")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"holds": ["lee", "scan:lee"]})
    assert "copy:lee" not in run.sim.world.holder
    codes = [r.action for r in run.stm.trace.actions() if isinstance(r.action, SendQR)]
    assert [c.operation for c in codes if c.purpose == "copy"] == ["scan"]


async def test_the_oracle_names_the_operation_of_its_work_step() -> None:
    office = _copy_and_scan()
    base = BaseInstruction(
        id="c1", requester="lee", text="scan my form", parts=(Part(kind="copy", operation="scan"),)
    )
    pools = classify(base, office)
    await verify_tasks(office, [_task(pools["L1"][0], office, 1)])


def test_a_seal_tool_is_found_by_its_property_not_its_id() -> None:
    raw = _raw()
    for t in raw["item_types"]:
        if t["id"] == "seal":
            t["id"], t["name"], t["seals"] = "chop", "company chop", True
    for p in raw["people"]:
        for o in p.get("owns", []):
            if o["type"] == "seal":
                o["type"] = "chop"
    office = parse_office(raw)
    stamper = office.owners_of("chop")[0]
    requester = next(p.id for p in office.people if p.id not in office.owners_of("chop"))
    stm = memory(requester, "please get my document stamped with the chop")
    answered(stm, stamper)
    code = SendQR(contact=stamper, item=f"document:{requester}", purpose="seal")
    assert check(office, stm, code) is None  # a party: they own the office's seal tool
    assert consent.consent_owner(office, requester, code.item, "seal", stamper) is None


def test_a_consuming_service_is_not_put_back() -> None:
    raw = _raw()
    raw["operations"].append(
        {"id": "shred", "name": "shred", "verbs": ["shred"], "input": "document", "consumes": True}
    )
    for f in raw["facilities"]:
        if f["id"] == "printer":
            f["operations"].append("shred")
    office = parse_office(raw)
    text = purpose_text(office, "heat", "document:lee", operation="shred")
    assert text == "take Lee Ming's document out and shred it"


async def test_a_treatment_after_a_fetch_of_the_same_item_starts_from_the_requester() -> None:
    """Round 4 (b6): a request read as two tasks on one item (bring my lunch from the fridge,
    then heat it): the second starts from the requester, who has it now, and counts only the
    hand-overs after the first task's, so the lunch is deposited again, heated and returned."""
    run = await run_instruction(load_office(), "lee", "Take my lunch out of the fridge and heat it")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert run.sim.world.check({"heated": "lunch:lee"})
    assert run.sim.world.check({"holds": ["lee", "lunch:lee"]})
