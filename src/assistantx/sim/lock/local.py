"""An in-process locker: the ``Locker`` interface straight over a ``LockController``.

The simulator uses it (with a ``SimClock``) so a hand-over costs no I/O. ``simulate_scan``
and ``simulate_close`` are the simulated person's acts at the locker; ``TcpLocker`` offers
the same two methods, so a simulator drives either one.
"""

from __future__ import annotations

from assistantx.adapters.lock.protocol.codes import CodeIssuer
from assistantx.core.clock import Clock
from assistantx.core.ports.lock import Locker, LockEvent, LockStatus, Purpose, QRCode
from assistantx.sim.lock.controller import LockController


class LocalLocker(Locker):
    def __init__(
        self,
        controller: LockController,
        *,
        clock: Clock | None = None,
        expiry_s: float = 15 * 60,
        render_png: bool = True,
    ) -> None:
        super().__init__()
        self.controller = controller
        # The assistant and the lock share the keyring object here; over TCP each holds a copy.
        self.issuer = CodeIssuer(
            controller.lock_id,
            controller.keyring,
            clock or controller.clock,
            expiry_s=expiry_s,
            render=render_png,
        )

    async def _start(self) -> None:
        self.controller.add_listener(self._publish)

    async def _stop(self) -> None:
        self.controller.remove_listener(self._publish)

    async def issue_code(
        self, *, instruction_id: str, person: str, purpose: Purpose, item: str
    ) -> QRCode:
        claims, payload = self.issuer.issue(
            instruction_id=instruction_id, person=person, purpose=purpose, item=item
        )
        self.controller.provision(payload)
        return await self.issuer.ato_qrcode(claims, payload)

    async def status(self) -> LockStatus:
        return self.controller.status()

    async def revoke(self, code_id: str) -> None:
        self.controller.revoke(code_id)

    async def open_for_maintenance(self, reason: str = "") -> LockEvent:
        return self.controller.open_for_maintenance(reason)

    async def simulate_scan(self, payload: str) -> LockEvent:
        """A person scans ``payload``; returns the code_accepted or code_rejected event."""
        return self.controller.scan(payload).decision

    async def simulate_close(self) -> LockEvent:
        """The person who opened the door shuts it; returns the door_closed event."""
        return self.controller.close()
