"""The ``Locker`` interface over the TCP lock link (a real locker or ``assistantx lock-sim``).

The assistant seals each code itself (it holds the code keyring too), provisions it at the
lock, and hands the payload and PNG to whoever sends it. Door events arrive on the link and
are published to subscribers exactly once each, across reconnects.
"""

from __future__ import annotations

from typing import Any

from assistantx.adapters.lock.protocol.client import LockClient
from assistantx.adapters.lock.protocol.codes import CodeIssuer
from assistantx.adapters.lock.protocol.keys import LockKeys
from assistantx.adapters.lock.protocol.link import LinkTimeouts
from assistantx.core.backoff import Backoff
from assistantx.core.clock import Clock, WallClock
from assistantx.core.errors import LockError, LockProtocolError
from assistantx.core.ports.lock import Locker, LockEvent, LockStatus, Purpose, QRCode


class TcpLocker(Locker):
    def __init__(
        self,
        host: str,
        port: int,
        keys: LockKeys,
        *,
        lock_id: str | None = None,
        clock: Clock | None = None,
        expiry_s: float = 15 * 60,
        timeouts: LinkTimeouts | None = None,
        backoff: Backoff | None = None,
        render_png: bool = True,
    ) -> None:
        """``lock_id``: the lock we expect; None takes whatever the lock announces."""
        super().__init__()
        self.keys = keys
        self.clock = clock or WallClock()
        self.expiry_s = expiry_s
        self.render_png = render_png
        self.client = LockClient(
            host,
            port,
            keys.link_key,
            lock_id=lock_id,
            timeouts=timeouts,
            backoff=backoff,
            on_event=self._publish,
        )
        self._issuer: CodeIssuer | None = None

    async def _start(self) -> None:
        await self.client.start()

    async def _stop(self) -> None:
        await self.client.stop()

    @property
    def issuer(self) -> CodeIssuer:
        if self._issuer is None:
            lock_id = self.client.lock_id
            if lock_id is None:
                raise LockError("the locker is not started")
            self._issuer = CodeIssuer(
                lock_id,
                self.keys.codes,
                self.clock,
                expiry_s=self.expiry_s,
                render=self.render_png,
            )
        return self._issuer

    async def issue_code(
        self, *, instruction_id: str, person: str, purpose: Purpose, item: str
    ) -> QRCode:
        claims, payload = self.issuer.issue(
            instruction_id=instruction_id, person=person, purpose=purpose, item=item
        )
        await self.client.request("provision", payload=payload)
        return await self.issuer.ato_qrcode(claims, payload)

    async def status(self) -> LockStatus:
        return LockStatus.model_validate(await self.client.request("status"))

    async def revoke(self, code_id: str) -> None:
        await self.client.request("revoke", code_id=code_id)

    async def open_for_maintenance(self, reason: str = "") -> LockEvent:
        return _event(await self.client.request("open", reason=reason))

    async def reload_keys(self) -> dict[str, Any]:
        """Ask the lock to re-read its key file (the first half of a key rotation)."""
        return await self.client.request("reload_keys")

    async def simulate_scan(self, payload: str) -> LockEvent:
        """Tell the emulator a person scanned ``payload``; the accepted or rejected event."""
        result = await self.client.request("scan", payload=payload)
        events = result.get("events")
        if not isinstance(events, list) or not events:
            raise LockProtocolError("scan answer without events")
        return LockEvent.model_validate(events[0])

    async def simulate_close(self) -> LockEvent:
        """Tell the emulator the person shut the door; the door_closed event."""
        return _event(await self.client.request("close"))


def _event(result: dict[str, Any]) -> LockEvent:
    try:
        return LockEvent.model_validate(result.get("event"))
    except ValueError as exc:
        raise LockProtocolError(f"malformed event in the lock's answer: {exc}") from exc
