"""People of the office at their own Matrix client: a plain ``MatrixClient`` that /syncs,
joins the rooms its user is invited to, keeps what arrives, and lets the test answer.

``expect`` hands out each received message once (oldest first among those that match), so a
test reads a conversation the way a person does: wait for the next message of a kind, then act.
"""

from __future__ import annotations

import asyncio
import contextlib
import io
import itertools
import logging
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import zxingcpp
from PIL import Image

from assistantx.adapters.messenger.matrix import MatrixClient
from synapse.helpers import WAIT_S, wait_joined
from synapse.homeserver import Account

logger = logging.getLogger(__name__)

_SYNC_TIMEOUT_MS = 500


@dataclass(frozen=True)
class Received:
    """One m.room.message event as the person's client saw it."""

    room_id: str
    event_id: str
    sender: str
    content: dict[str, Any]

    @property
    def msgtype(self) -> str:
        return str(self.content.get("msgtype", ""))

    @property
    def body(self) -> str:
        return str(self.content.get("body", ""))


class MatrixPerson:
    def __init__(self, name: str, account: Account, homeserver_url: str) -> None:
        self.name = name
        self.user_id = account.user_id
        self.client = MatrixClient(homeserver_url, account.access_token)
        self.received: list[Received] = []  # every message from others, in arrival order
        self._taken: set[str] = set()
        self._txn = itertools.count(1)
        self._changed = asyncio.Condition()
        self._task: asyncio.Task[None] | None = None

    # -- the client's sync loop ------------------------------------------------------------

    async def start(self) -> None:
        # The first sync only takes the position: what happened before the test is not news.
        first = await self.client.sync(since=None, timeout_ms=0, filter_json=None)
        self._task = asyncio.create_task(self._run(str(first["next_batch"])), name=self.name)

    async def stop(self) -> None:
        task, self._task = self._task, None
        if task is not None:
            task.cancel()
            with contextlib.suppress(asyncio.CancelledError):
                await task
        await self.client.aclose()

    async def _run(self, since: str) -> None:
        while True:
            response = await self.client.sync(
                since=since, timeout_ms=_SYNC_TIMEOUT_MS, filter_json=None
            )
            since = str(response["next_batch"])
            rooms = response.get("rooms", {})
            for room_id in rooms.get("invite", {}):
                await self.client.join(room_id)  # people accept the assistant's DMs
            fresh = [
                Received(room_id, e["event_id"], e["sender"], e.get("content", {}))
                for room_id, room in rooms.get("join", {}).items()
                for e in room.get("timeline", {}).get("events", [])
                if e.get("type") == "m.room.message" and e.get("sender") != self.user_id
            ]
            if fresh:
                async with self._changed:
                    self.received.extend(fresh)
                    self._changed.notify_all()

    # -- what a person does ----------------------------------------------------------------

    async def expect(
        self,
        *,
        sender: str | None = None,
        room: str | None = None,
        msgtype: str | None = None,
        not_room: str | None = None,
        timeout_s: float = WAIT_S,
    ) -> Received:
        """The oldest message not yet taken that matches; waits for it if need be."""

        def match(m: Received) -> bool:
            return (
                m.event_id not in self._taken
                and (sender is None or m.sender == sender)
                and (room is None or m.room_id == room)
                and (not_room is None or m.room_id != not_room)
                and (msgtype is None or m.msgtype == msgtype)
            )

        found: list[Received] = []

        def ready() -> bool:
            found[:] = [m for m in self.received if match(m)][:1]
            return bool(found)

        try:
            async with asyncio.timeout(timeout_s), self._changed:
                await self._changed.wait_for(ready)
        except TimeoutError:
            seen = [(m.room_id, m.sender, m.msgtype, m.body) for m in self.received]
            raise AssertionError(
                f"{self.name} got no message from {sender} in {room} ({msgtype}) within "
                f"{timeout_s}s; received: {seen}"
            ) from None
        self._taken.add(found[0].event_id)
        return found[0]

    def messages(self, predicate: Callable[[Received], bool] = lambda m: True) -> list[Received]:
        return [m for m in self.received if predicate(m)]

    async def say(self, room_id: str, text: str) -> str:
        return await self.client.send_event(
            room_id,
            "m.room.message",
            {"msgtype": "m.text", "body": text},
            txn_id=f"{self.name}-{next(self._txn)}",
        )

    async def open_dm(self, user_id: str, *, also_wait_for: tuple[str, ...] = ()) -> str:
        """A direct chat with ``user_id``; returns once it (and ``also_wait_for``) joined."""
        room = await self.client.create_room(invite=[user_id], is_direct=True)
        for member in (user_id, *also_wait_for):
            await wait_joined(self.client, room, member)
        return room

    async def read_qr(self, image: Received) -> str:
        """Download an image message and read the QR code in it, as a phone camera would."""
        assert image.msgtype == "m.image", image
        data = await self.client.download(str(image.content["url"]))
        codes = zxingcpp.read_barcodes(Image.open(io.BytesIO(data)))
        assert len(codes) == 1, f"{len(codes)} QR codes in {image.body}"
        return str(codes[0].text)
