"""The in-process Locker the simulator uses."""

from __future__ import annotations

import pytest

from assistantx.core.clock import SimClock
from assistantx.core.ports import lock as lock_port
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.local import LocalLocker
from helpers.eventually import assert_quiet


async def test_hand_over_through_the_locker_interface(
    controller: LockController, clock: SimClock
) -> None:
    async with LocalLocker(controller, expiry_s=300) as locker:
        events = locker.subscribe()
        qr = await locker.issue_code(
            instruction_id="ins-3", person="zhang", purpose="collect", item="key:zhang"
        )
        assert qr.png is not None
        assert qr.png.startswith(b"\x89PNG")
        assert (qr.person, qr.lock_id, qr.expires_at) == ("zhang", "locker-1", 1_300.0)
        assert (await locker.status()).active_codes == 1

        accepted = await locker.simulate_scan(qr.payload)
        assert (accepted.kind, accepted.person, accepted.code_id) == (
            "code_accepted",
            "zhang",
            qr.code_id,
        )
        closed = await locker.simulate_close()
        assert (closed.kind, closed.person, closed.instruction_id) == (
            "door_closed",
            "zhang",
            "ins-3",
        )
        replay = await locker.simulate_scan(qr.payload)
        assert (replay.kind, replay.reason) == ("code_rejected", "replayed")

        received = [events.get_nowait() for _ in range(events.qsize())]
        assert [e.kind for e in received] == [
            "code_accepted",
            "door_opened",
            "door_closed",
            "code_rejected",
        ]
        assert [e.seq for e in received] == [1, 2, 3, 4]
    # Stopped: no more events reach subscribers.
    controller.open_for_maintenance()
    await assert_quiet(events, 0.05, what="event after the locker stopped")


async def test_revoke_and_expiry_through_the_locker(
    controller: LockController, clock: SimClock
) -> None:
    async with LocalLocker(controller, expiry_s=60, render_png=False) as locker:
        revoked = await locker.issue_code(
            instruction_id="i", person="lee", purpose="sign", item="doc"
        )
        assert revoked.png is None
        await locker.revoke(revoked.code_id)
        assert (await locker.simulate_scan(revoked.payload)).reason == "revoked"
        late = await locker.issue_code(instruction_id="i", person="lee", purpose="sign", item="d")
        await clock.sleep(61)
        assert (await locker.simulate_scan(late.payload)).reason == "expired"
        assert (await locker.status()).active_codes == 0


async def _hand_over(locker: LocalLocker, n: int) -> str:
    """Person ``n`` collects an item with a fresh code; its code id."""
    qr = await locker.issue_code(
        instruction_id=f"ins-{n}", person="zhang", purpose="collect", item=f"doc-{n}"
    )
    await locker.simulate_scan(qr.payload)
    await locker.simulate_close()
    return qr.code_id


async def test_the_reports_of_the_latest_codes_are_kept(
    controller: LockController, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(lock_port, "CODE_REPORTS_KEPT", 3)
    async with LocalLocker(controller, expiry_s=60, render_png=False) as locker:
        codes = [await _hand_over(locker, n) for n in range(5)]
        assert locker.code_states == {c: "used" for c in codes[2:]}


async def test_a_code_reported_again_is_kept_as_the_latest(
    controller: LockController, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(lock_port, "CODE_REPORTS_KEPT", 2)
    async with LocalLocker(controller, expiry_s=60, render_png=False) as locker:
        locker.report_code("a", "scanned")
        locker.report_code("b", "used")
        locker.report_code("a", "used")  # its door closed: now the latest report
        locker.report_code("c", "scanned")
        assert locker.code_states == {"a": "used", "c": "scanned"}


def test_the_reports_kept_are_bounded(controller: LockController) -> None:
    locker = LocalLocker(controller, expiry_s=60, render_png=False)
    for n in range(3 * lock_port.CODE_REPORTS_KEPT):
        locker.report_code(f"code-{n}", "scanned" if n % 2 else "used")
    assert len(locker.code_states) == lock_port.CODE_REPORTS_KEPT
    assert next(iter(locker.code_states)) == f"code-{2 * lock_port.CODE_REPORTS_KEPT}"
