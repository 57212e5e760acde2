"""Memory stays flat over time: bounded evidence, the latest update per fact, and a restore
from a snapshot plus the journaled updates after it."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from assistantx.core.office import Office, load_office
from assistantx.memory.graph import HISTORY, LongTermMemory
from assistantx.memory.updates import AvailabilityUpdate, OwnershipUpdate
from assistantx.service.durability import LTM_STATE, Durability
from assistantx.store.journal import Journal


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


def test_history_is_bounded_and_the_latest_per_fact_kept(office: Office) -> None:
    m = LongTermMemory(office)
    m.apply(OwnershipUpdate(person="gao", item_type="stapler", owns=True, evidence="gao"), 0.0)
    for n in range(5 * HISTORY):
        person = ("wang", "zhang")[n % 2]
        m.apply(AvailabilityUpdate(person=person, available=n % 3 == 0, evidence=f"e{n}"), n)
    assert len(m.updates) == HISTORY
    assert m.updates[-1].update.evidence == f"e{5 * HISTORY - 1}"
    assert m.applied_total == 5 * HISTORY + 1
    latest = {k: u.update.evidence for k, u in m.latest.items()}
    # The ownership fact fell out of the history, but its latest evidence is kept.
    assert latest == {
        "ownership:gao:stapler": "gao",
        "availability:wang": f"e{5 * HISTORY - 2}",
        "availability:zhang": f"e{5 * HISTORY - 1}",
    }
    small = len(json.dumps(m.snapshot()))
    for n in range(5 * HISTORY):
        m.apply(AvailabilityUpdate(person="wang", available=True, evidence=f"more {n}"), n)
    assert len(json.dumps(m.snapshot())) < 1.1 * small  # does not grow with use
    restored = LongTermMemory.restore(office, json.loads(json.dumps(m.snapshot())))
    assert restored.latest.keys() == m.latest.keys()
    assert restored.ownership("gao", "stapler") is True


def test_restore_replays_the_updates_journaled_after_the_snapshot(
    office: Office, tmp_path: Path
) -> None:
    journal = Journal.open(tmp_path / "j.sqlite3")
    m = LongTermMemory(office)
    first = m.apply(AvailabilityUpdate(person="wang", available=False, evidence="a"), 1.0)
    journal.record_memory_update(1.0, "i1", first.model_dump(mode="json"))
    journal.put_memory_snapshot(LTM_STATE, m.snapshot())
    later = m.apply(OwnershipUpdate(person="gao", item_type="stapler", owns=True, evidence="b"), 2)
    journal.record_memory_update(2.0, "i2", later.model_dump(mode="json"))
    restored = Durability.restore_memory(journal, office)
    assert restored is not None
    assert restored.availability("wang") == "unavailable"
    assert restored.ownership("gao", "stapler") is True  # only in the journaled update
    assert restored.applied_total == 2
    journal.close()


def test_owner_indexes_follow_updates_and_restores(office: Office) -> None:
    m = LongTermMemory(office)
    before = m.owners("stapler")
    m.apply(OwnershipUpdate(person="gao", item_type="stapler", owns=True, evidence="e"), 1.0)
    m.apply(OwnershipUpdate(person="wang", item_type="stapler", owns=False, evidence="e"), 2.0)
    m.apply(OwnershipUpdate(person="lin", item_type="pen", owns=False, evidence="e"), 3.0)
    assert m.owners("stapler") == sorted({*before, "gao"} - {"wang"})
    assert m.known_not_owners("stapler") == ["wang"]
    assert m.known_not_owners("pen") == ["lin"]
    m.apply(OwnershipUpdate(person="lin", item_type="pen", owns=True, evidence="e"), 4.0)
    assert m.known_not_owners("pen") == []
    assert "lin" in m.owners("pen")
    restored = LongTermMemory.restore(office, json.loads(json.dumps(m.snapshot())))
    assert restored.owners("stapler") == m.owners("stapler")
    assert restored.known_not_owners("stapler") == ["wang"]


def test_id_lookups_follow_a_copy_with_other_people(office: Office) -> None:
    assert office.person("sun").id == "sun"  # fills the index
    extra = office.person("sun").model_copy(update={"id": "sun_2", "name": "Sun Li 2"})
    bigger = office.model_copy(update={"people": (*office.people, extra)})
    assert bigger.person("sun_2").name == "Sun Li 2"
    with pytest.raises(KeyError, match="sun_2"):
        office.person("sun_2")
