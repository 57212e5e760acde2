"""/v1/memory and /v1/people: the belief graph as JSON, and the operator's corrections.

Who reads what: the graph (people, places, availability, ownership) is the office's shared
directory, readable with any token. The applied updates carry instruction ids and evidence
that quotes people's direct messages word for word, so a person token sees only the updates
made by their own instructions; the operator sees all of them. ``/v1/people/{id}`` carries no
evidence and no instruction ids.
"""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter

from assistantx.memory.graph import LongTermMemory, lid, pid
from assistantx.memory.updates import AvailabilityUpdate, OwnershipUpdate
from assistantx.service.deps import Caller, Runtime
from assistantx.service.durability import LTM_STATE
from assistantx.service.runtime import ServiceRuntime
from assistantx.service.schemas import PersonOut, PersonPatch

router = APIRouter(prefix="/v1", tags=["memory"])


@router.get("/memory")
async def get_memory(runtime: Runtime, caller: Caller) -> dict[str, Any]:
    """The long-term memory graph (node-link JSON) and the updates applied to it (a person
    sees only the updates their own instructions made)."""
    snapshot = runtime.assistant.ltm.snapshot()
    if caller.person is not None:
        for key in ("updates", "latest"):  # both carry instruction ids and quoted evidence
            snapshot[key] = _own_updates(runtime, caller.person, snapshot[key])
    return snapshot


def _own_updates(
    runtime: ServiceRuntime, person: str, updates: list[dict[str, Any]]
) -> list[dict[str, Any]]:
    mine: dict[str, bool] = {}
    kept = []
    for update in updates:
        instruction_id = update.get("instruction_id")
        if not isinstance(instruction_id, str):
            continue  # the operator's corrections
        if instruction_id not in mine:
            record = runtime.journal.instruction(instruction_id)
            mine[instruction_id] = record is not None and record.requester == person
        if mine[instruction_id]:
            kept.append(update)
    return kept


def _person(ltm: LongTermMemory, person_id: str) -> PersonOut:
    node = ltm.graph.nodes[pid(person_id)]
    return PersonOut(
        id=person_id,
        name=str(node.get("name", person_id)),
        available=ltm.availability(person_id),
        observed_at=ltm.availability_observed_at(person_id),
        location=ltm.location_of(person_id),
        items=ltm.items_of(person_id),
        groups=ltm.groups_of(person_id),
    )


@router.get("/people/{person}", response_model=PersonOut)
async def get_person(person: str, runtime: Runtime, caller: Caller) -> PersonOut:
    return _person(runtime.assistant.ltm, runtime.resolver.person(person))


@router.patch("/people/{person}", response_model=PersonOut)
async def patch_person(
    person: str, body: PersonPatch, runtime: Runtime, caller: Caller
) -> PersonOut:
    """Set availability (true/false/null = unknown) and/or desk location. Operator only."""
    caller.require_operator()
    person_id = runtime.resolver.person(person)
    ltm = runtime.assistant.ltm
    location = runtime.resolver.place(body.location) if body.location else None
    if "available" in body.model_fields_set:
        update = AvailabilityUpdate(
            person=person_id, available=body.available, evidence=body.evidence
        )
        await _record(runtime, ltm.apply(update, runtime.clock.now()).model_dump(mode="json"))
    if location is not None:
        _move(ltm, person_id, location)
    await runtime.journal.aput_memory_snapshot(LTM_STATE, ltm.snapshot())
    return _person(ltm, person_id)


@router.put("/people/{person}/items/{item_type}", response_model=PersonOut)
async def put_item(person: str, item_type: str, runtime: Runtime, caller: Caller) -> PersonOut:
    """Memory now believes ``person`` owns an item of ``item_type``. Operator only."""
    return await _ownership(person, item_type, True, runtime, caller)


@router.delete("/people/{person}/items/{item_type}", response_model=PersonOut)
async def delete_item(person: str, item_type: str, runtime: Runtime, caller: Caller) -> PersonOut:
    """Memory now believes ``person`` owns no item of ``item_type``. Operator only."""
    return await _ownership(person, item_type, False, runtime, caller)


async def _ownership(
    person: str, item_type: str, owns: bool, runtime: ServiceRuntime, caller: Caller
) -> PersonOut:
    caller.require_operator()
    person_id = runtime.resolver.person(person)
    type_id = runtime.resolver.item_type(item_type)
    ltm = runtime.assistant.ltm
    update = OwnershipUpdate(
        person=person_id, item_type=type_id, owns=owns, evidence="set by the operator"
    )
    await _record(runtime, ltm.apply(update, runtime.clock.now()).model_dump(mode="json"))
    await runtime.journal.aput_memory_snapshot(LTM_STATE, ltm.snapshot())
    return _person(ltm, person_id)


async def _record(runtime: ServiceRuntime, applied: dict[str, Any]) -> None:
    await runtime.journal.arecord_memory_update(runtime.clock.now(), None, applied)


def _move(ltm: LongTermMemory, person_id: str, location_id: str) -> None:
    """Rewire the person's one ``at`` edge to the new location."""
    node = pid(person_id)
    for other in [n for n in ltm.graph.neighbors(node) if ltm.graph.edges[node, n]["rel"] == "at"]:
        ltm.graph.remove_edge(node, other)
    ltm.graph.add_edge(node, lid(location_id), rel="at")
