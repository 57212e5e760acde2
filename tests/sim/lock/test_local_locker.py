"""The in-process Locker the simulator uses."""

from __future__ import annotations

from assistantx.core.clock import SimClock
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
