"""The locker's logic: scans accepted once, every rejection with its reason, events."""

from __future__ import annotations

import pytest

from assistantx.adapters.lock.protocol import CodeIssuer, Keyring, LockKeys
from assistantx.adapters.lock.protocol.keys import new_key
from assistantx.core.clock import SimClock
from assistantx.core.errors import InvalidCodeError, LockCommandError
from assistantx.core.ports.lock import LockEvent
from assistantx.sim.lock.controller import LockController
from helpers.lock import LOCK_ID


def _provisioned(issuer: CodeIssuer, controller: LockController, **overrides: str) -> str:
    fields = {"instruction_id": "ins-1", "person": "lee", "item": "document:lee"}
    fields.update(overrides)
    _, payload = issuer.issue(purpose="deposit", **fields)
    controller.provision(payload)
    return payload


def test_a_full_hand_over_is_attributed(issuer: CodeIssuer, controller: LockController) -> None:
    seen: list[LockEvent] = []
    controller.add_listener(seen.append)
    payload = _provisioned(issuer, controller)
    assert controller.status().active_codes == 1

    result = controller.scan(payload)
    assert result.accepted
    assert [e.kind for e in result.events] == ["code_accepted", "door_opened"]
    assert controller.status().door == "open"
    assert not controller.status().locked

    closed = controller.close()
    assert closed.kind == "door_closed"
    assert [e.seq for e in seen] == [1, 2, 3]
    assert {(e.person, e.instruction_id) for e in seen} == {("lee", "ins-1")}
    status = controller.status()
    assert (status.door, status.locked, status.active_codes) == ("closed", True, 0)
    assert status.contents == ["document:lee"]


def test_a_code_opens_the_door_only_once(issuer: CodeIssuer, controller: LockController) -> None:
    payload = _provisioned(issuer, controller)
    assert controller.scan(payload).accepted
    controller.close()
    replay = controller.scan(payload)
    assert not replay.accepted
    assert replay.decision.reason == "replayed"
    assert replay.decision.person == "lee"
    assert controller.status().door == "closed"


def test_an_expired_code_is_rejected(
    issuer: CodeIssuer, controller: LockController, clock: SimClock
) -> None:
    payload = _provisioned(issuer, controller)
    clock.advance(601)
    result = controller.scan(payload)
    assert result.decision.reason == "expired"
    assert controller.status().active_codes == 0  # forgotten once expired


def test_other_lock_revoked_and_unprovisioned_codes_are_rejected(
    keys: LockKeys, clock: SimClock, controller: LockController, issuer: CodeIssuer
) -> None:
    other = CodeIssuer("locker-2", keys.codes, clock, render=False)
    _, foreign = other.issue(instruction_id="i", person="lee", purpose="collect", item="x")
    assert controller.scan(foreign).decision.reason == "other_lock"
    with pytest.raises(InvalidCodeError, match="locker-2"):
        controller.provision(foreign)

    _, never_sent = issuer.issue(instruction_id="i", person="lee", purpose="collect", item="x")
    assert controller.scan(never_sent).decision.reason == "not_provisioned"

    claims, revoked = issuer.issue(instruction_id="i", person="lee", purpose="collect", item="x")
    controller.provision(revoked)
    controller.revoke(claims.code_id)
    assert controller.scan(revoked).decision.reason == "revoked"
    with pytest.raises(LockCommandError) as caught:
        controller.revoke(claims.code_id)
    assert caught.value.kind == "unknown_code"


def test_forged_and_garbage_scans_are_rejected_with_a_reason(
    controller: LockController, clock: SimClock
) -> None:
    forger = CodeIssuer(LOCK_ID, Keyring.single("k0", new_key()), clock, render=False)
    _, forged = forger.issue(instruction_id="i", person="mallory", purpose="collect", item="x")
    assert controller.scan(forged).decision.reason == "forged"
    assert controller.scan("hello").decision.reason == "malformed"
    assert controller.scan(forged[:30]).decision.reason in ("malformed", "forged")
    with pytest.raises(InvalidCodeError):
        controller.provision(forged)
    assert controller.status().door == "closed"


def test_a_scan_while_the_door_is_open_spends_nothing(
    issuer: CodeIssuer, controller: LockController
) -> None:
    first = _provisioned(issuer, controller)
    second = _provisioned(issuer, controller, person="zhang")
    assert controller.scan(first).accepted
    assert controller.scan(second).decision.reason == "door_open"
    closed = controller.close()
    assert closed.person == "lee"
    result = controller.scan(second)
    assert result.accepted
    assert controller.close().person == "zhang"


def test_a_code_from_the_future_is_not_yet_valid(
    keys: LockKeys, controller: LockController
) -> None:
    future = CodeIssuer(LOCK_ID, keys.codes, SimClock(start=10_000.0), render=False)
    _, payload = future.issue(instruction_id="i", person="lee", purpose="collect", item="x")
    controller.provision(payload)
    assert controller.scan(payload).decision.reason == "not_yet_valid"


def test_door_commands_check_the_door(controller: LockController) -> None:
    with pytest.raises(LockCommandError) as caught:
        controller.close()
    assert caught.value.kind == "door_closed"
    opened = controller.open_for_maintenance("battery")
    assert (opened.kind, opened.person, opened.reason) == ("door_opened", "maintenance", "battery")
    with pytest.raises(LockCommandError):
        controller.open_for_maintenance()
    assert controller.close().person == "maintenance"


def test_the_event_log_is_bounded_and_says_when_it_lost_events(
    keys: LockKeys, clock: SimClock
) -> None:
    controller = LockController(LOCK_ID, keys.codes, clock, event_log_size=4)
    for _ in range(5):
        controller.open_for_maintenance()
        controller.close()
    assert controller.last_seq == 10
    recent = controller.events_since(7, controller.epoch)
    assert [e.seq for e in recent.events] == [8, 9, 10]
    assert recent.complete
    stale = controller.events_since(2, controller.epoch)
    assert [e.seq for e in stale.events] == [7, 8, 9, 10]
    assert not stale.complete
    restarted = controller.events_since(9, "another-epoch")
    assert [e.seq for e in restarted.events] == [7, 8, 9, 10]
    assert not restarted.complete


def test_a_failing_listener_does_not_stop_the_lock(controller: LockController) -> None:
    def broken(event: LockEvent) -> None:
        raise RuntimeError("subscriber bug")

    seen: list[LockEvent] = []
    controller.add_listener(broken)
    controller.add_listener(seen.append)
    controller.open_for_maintenance()
    assert [e.kind for e in seen] == ["door_opened"]
